// Linearly transformed cosines along a segment light (after Heitz and Hill 2017, "Real-time
// line- and disk-light shading with linearly transformed cosines").
//
//   float ltcLineIntegral(mat3 minv, vec3 p0, vec3 p1)
//
// The mean over the segment p0..p1 (relative to the shading point, in the shading frame: +z the
// normal) of D(w) / d^2, D the cosine lobe moved by M (given M^-1, normalised to 1 over the
// sphere) and d the distance: a tube of intensity I spread evenly along its length (the
// engine's tube, as lineIrradiance assumes: each element a point light of I dl / length) gives
// the lobe integral I * ltcLineIntegral, in 1 / m^2. With M^-1 = identity, pi times it is the
// segment's mean cos / d^2: lineIrradiance without its bias and with an exact horizon.
//
// How: moved by M^-1, the segment stays a segment p'(t) = a' + t b', and
//   D(w) / d^2 = |det M^-1| / pi * p'.z |p| / |p'|^4.
// Without the |p| factor (a thin Lambertian cylinder's sin(phi) cancels it, Heitz and Hill's
// case) the integrand is rational in t; for the isotropic line |p| is interpolated linearly over
// kLtcLinePieces pieces (|p| is a convex, slowly varying function of t), which leaves the
// integrals of t^k / |p'|^4, k = 0..2, all in closed form. The segment is first cut where
// p.z = 0 and where p'.z = 0: nothing below either horizon is integrated.
#ifndef CANDELA_LTC_LINE_GLSL
#define CANDELA_LTC_LINE_GLSL

#include "common/math.glsl"

// 8: the report's worst tube cell (roughness 1, 2 m at 1 m) is 3.0 % off, 4.1 % with 4 pieces.
const int kLtcLinePieces = 8;

// Antiderivatives at t of t^k / Q(t)^2, k = 0, 1, 2, for Q = c2 t^2 + c1 t + c0 with
// delta = 4 c0 c2 - c1^2 > 0 (Q has no real root: the segment misses the shading point).
vec3 ltcQuadraticAntiderivatives(float t, float c0, float c1, float c2, float delta) {
    float q = (c2 * t + c1) * t + c0;
    float rootDelta = sqrt(delta);
    float j = (2.0 / rootDelta) * atan((2.0 * c2 * t + c1) / rootDelta);  // integral of 1 / Q
    float i0 = (2.0 * c2 * t + c1) / (delta * q) + (2.0 * c2 / delta) * j;
    float i1 = -(c1 * t + 2.0 * c0) / (delta * q) - (c1 / delta) * j;
    float i2 = (j - c1 * i1 - c0 * i0) / c2;  // t^2 = (Q - c1 t - c0) / c2
    return vec3(i0, i1, i2);
}

// The part of `range` where z0 + t dz >= 0 (empty: x >= y).
vec2 ltcAboveHorizon(float z0, float dz, vec2 range) {
    if (dz > 0.0) range.x = max(range.x, -z0 / dz);
    else if (dz < 0.0) range.y = min(range.y, -z0 / dz);
    else if (z0 < 0.0) range = vec2(1.0, 0.0);
    return range;
}

float ltcLineIntegral(mat3 minv, vec3 p0, vec3 p1) {
    vec3 a = minv * p0;
    vec3 b = minv * (p1 - p0);
    // Horizon: the part of t in [0, 1] above both the surface's horizon and the moved cosine's
    // (M^-1 can lift directions under the surface's horizon above the moved one).
    vec2 range = ltcAboveHorizon(p0.z, p1.z - p0.z, ltcAboveHorizon(a.z, b.z, vec2(0.0, 1.0)));
    float t0 = range.x, t1 = range.y;
    if (!(t1 > t0)) return 0.0;
    vec3 ab = cross(a, b);
    float c2 = dot(b, b);
    float c1 = 2.0 * dot(a, b);
    float c0 = dot(a, a);
    float delta = 4.0 * dot(ab, ab);
    // A segment through the shading point (or of zero length) delivers nothing finite.
    if (!(delta > 1e-30 * c0 * c2) || c2 <= 0.0) return 0.0;
    vec3 d = p1 - p0;
    float sum = 0.0;
    float tPrevious = t0;
    vec3 previous = ltcQuadraticAntiderivatives(t0, c0, c1, c2, delta);
    float rPrevious = length(p0 + t0 * d);
    for (int k = 1; k <= kLtcLinePieces; ++k) {
        float t = mix(t0, t1, float(k) / float(kLtcLinePieces));
        vec3 current = ltcQuadraticAntiderivatives(t, c0, c1, c2, delta);
        float r = length(p0 + t * d);
        // |p| ~ r0 + s t on the piece; p'.z = a.z + b.z t; their product's coefficients.
        float s = (r - rPrevious) / max(t - tPrevious, 1e-30);
        float r0 = rPrevious - s * tPrevious;
        vec3 coefficients = vec3(r0 * a.z, r0 * b.z + s * a.z, s * b.z);
        sum += dot(coefficients, current - previous);
        previous = current;
        rPrevious = r;
        tPrevious = t;
    }
    return max(sum, 0.0) * abs(determinant(minv)) / PI;
}

// The mean over t of D(w) sin(phi) / d^2 along the segment, phi the angle between the segment
// and the direction to the element: a thin Lambertian cylinder's element of length dl and width
// w has intensity L w sin(phi) dl, so the cylinder's lobe integral is L w |p1 - p0| times this.
// sin(phi) = h / |p| (h the distance from the shading point to the segment's line) cancels the
// isotropic line's |p| (Heitz and Hill 2017's case): the integrand is h p'.z / |p'|^4, rational
// in t, so one closed form over the whole range, with no pieces and no loop.
float ltcCylinderIntegral(mat3 minv, vec3 p0, vec3 p1) {
    vec3 a = minv * p0;
    vec3 b = minv * (p1 - p0);
    vec2 range = ltcAboveHorizon(p0.z, p1.z - p0.z, ltcAboveHorizon(a.z, b.z, vec2(0.0, 1.0)));
    if (!(range.y > range.x)) return 0.0;
    vec3 ab = cross(a, b);
    float c2 = dot(b, b);
    float c1 = 2.0 * dot(a, b);
    float c0 = dot(a, a);
    float delta = 4.0 * dot(ab, ab);
    if (!(delta > 1e-30 * c0 * c2) || c2 <= 0.0) return 0.0;
    vec3 d = p1 - p0;
    vec3 pxd = cross(p0, d);
    float h = sqrt(dot(pxd, pxd) / dot(d, d));  // distance to the line
    vec3 integrals = ltcQuadraticAntiderivatives(range.y, c0, c1, c2, delta) -
                     ltcQuadraticAntiderivatives(range.x, c0, c1, c2, delta);
    float sum = h * (a.z * integrals.x + b.z * integrals.y);
    return max(sum, 0.0) * abs(determinant(minv)) / PI;
}

#endif
