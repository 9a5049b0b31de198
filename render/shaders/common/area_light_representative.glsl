// Drobot's "representative" area lights (2014, GPU Pro 5, "Physically Based Area Lights", written
// for Killzone Shadow Fall) for the one-sided rect and disk lights of area_lights.glsl: one
// most-important point per lobe instead of an integral. Everything is in world space, relative to
// the shading point P; the light's plane passes through `center` with unit emitting normal
// `normal`.
#ifndef CANDELA_AREA_LIGHT_REPRESENTATIVE_GLSL
#define CANDELA_AREA_LIGHT_REPRESENTATIVE_GLSL

#include "common/math.glsl"

// A rect or disk in its plane: centre, emitting normal, in-plane axes, half extents (a disk
// has halfSize = (r, r) and isDisk).
struct AreaShape {
    vec3 center;
    vec3 normal;
    vec3 axisX;
    vec3 axisY;
    vec2 halfSize;
    bool isDisk;
};

vec2 areaPlaneCoords(AreaShape s, vec3 point) {
    vec3 d = point - s.center;
    return vec2(dot(d, s.axisX), dot(d, s.axisY));
}

vec3 areaPlanePoint(AreaShape s, vec2 uv) {
    return s.center + s.axisX * uv.x + s.axisY * uv.y;
}

// The point of the shape nearest to uv (uv itself when inside).
vec2 clampToAreaShape(AreaShape s, vec2 uv) {
    if (s.isDisk) {
        float len = length(uv);
        return len > s.halfSize.x ? uv * (s.halfSize.x / len) : uv;
    }
    return clamp(uv, -s.halfSize, s.halfSize);
}

float areaShapeArea(AreaShape s) {
    return s.isDisk ? PI * s.halfSize.x * s.halfSize.x : 4.0 * s.halfSize.x * s.halfSize.y;
}

// Where the ray P + t dir (t > 0) meets the light's plane, in plane coordinates; `hit` false
// when it runs parallel to or away from the plane (then `fallback` is returned).
vec2 areaPlaneHit(AreaShape s, vec3 P, vec3 dir, vec2 fallback, out bool hit, out float t) {
    float height = dot(P - s.center, s.normal);  // > 0 in front of the light
    float approach = -dot(dir, s.normal);
    hit = approach > 1e-6 && height > 0.0;
    t = hit ? height / approach : 0.0;
    return hit ? areaPlaneCoords(s, P + dir * t) : fallback;
}

// Irradiance per unit luminance from the whole shape, sampled at one point of it: the
// Drobot's area x cos(surface) x cos(light) / d^2, with d^2 + A / pi in the denominator so a disk
// seen along its axis gets the exact form factor pi r^2 / (d^2 + r^2) and a large light does
// not blow up at small distances.
float areaPointIrradiance(AreaShape s, vec3 P, vec3 N, vec3 samplePoint, float area, out vec3 L) {
    vec3 toSample = samplePoint - P;
    float distSq = max(dot(toSample, toSample), 1e-12);
    L = toSample * inversesqrt(distSq);
    float cosLight = saturate(-dot(L, s.normal));
    return area * saturate(dot(N, L)) * cosLight / (distSq + area / PI);
}

// Diffuse: the most important point. p_c where the cosine is largest (the normal ray's hit,
// clamped to the shape), p_r where the distance is smallest (P projected onto the plane,
// clamped); the sample is where their half vector meets the plane. `unclamped` is Drobot's
// cheaper variant: the half vector of the unclamped hit and projection.
float areaRepresentativeDiffuse(AreaShape s, vec3 P, vec3 N, bool unclamped, out vec3 L) {
    float height = dot(P - s.center, s.normal);
    if (height <= 0.0) {
        L = safeNormalize(s.center - P);
        return 0.0;
    }
    vec2 projected = areaPlaneCoords(s, P);  // p'' (P - normal * height)
    bool hit;
    float t;
    vec2 normalHit = areaPlaneHit(s, P, N, projected, hit, t);  // p' (p'' when N looks away)
    vec2 pc = unclamped ? normalHit : clampToAreaShape(s, normalHit);
    vec2 pr = unclamped ? projected : clampToAreaShape(s, projected);
    vec3 towardsC = safeNormalize(areaPlanePoint(s, pc) - P);
    vec3 towardsR = safeNormalize(areaPlanePoint(s, pr) - P);
    vec3 halfVector = safeNormalize(towardsC + towardsR);
    vec2 pd = areaPlaneHit(s, P, halfVector, pr, hit, t);
    pd = clampToAreaShape(s, pd);
    return areaPointIrradiance(s, P, N, areaPlanePoint(s, pd), areaShapeArea(s), L);
}

// Specular: the cone around R with apex angle alpha(g) = 2 sqrt(2 / (g + 2)). With the
// Blinn-Phong gloss of a GGX alpha, g = 2 / alpha^2 - 2, the apex is 2 alpha: a cone of half
// angle alpha (alpha = roughness^2). Its footprint on the plane (a circle of radius t tan alpha
// at the hit distance t) is intersected with the shape, both taken as squares of their own
// area: [lo, hi] in plane coordinates; false when R misses the plane or the shape.
bool areaSpecularConeFootprint(AreaShape s, vec3 P, vec3 R, float alpha, out vec2 lo,
                               out vec2 hi) {
    bool hit;
    float t;
    vec2 q = areaPlaneHit(s, P, R, vec2(0.0), hit, t);
    const float kSquareOfDisc = 0.886226925;  // sqrt(pi) / 2: half side of a unit disc's square
    float footprint = t * tan(min(alpha, 1.5)) * kSquareOfDisc;
    vec2 shapeHalf = s.isDisk ? s.halfSize * kSquareOfDisc : s.halfSize;
    lo = max(q - footprint, -shapeHalf);
    hi = min(q + footprint, shapeHalf);
    return hit && all(greaterThan(hi, lo));
}

// The intersection's centre gives the direction and its area the normalisation. Returns the
// illuminance per unit luminance for the BRDF evaluated along L.
float areaRepresentativeSpecular(AreaShape s, vec3 P, vec3 N, vec3 R, float alpha, out vec3 L) {
    L = R;
    vec2 lo, hi;
    if (!areaSpecularConeFootprint(s, P, R, alpha, lo, hi)) return 0.0;
    vec2 extent = hi - lo;
    return areaPointIrradiance(s, P, N, areaPlanePoint(s, 0.5 * (lo + hi)), extent.x * extent.y,
                               L);
}

#endif
