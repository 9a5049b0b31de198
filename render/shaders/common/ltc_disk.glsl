// Linearly transformed cosines over a one-sided disk or ellipse (Heitz and Hill 2017,
// "Real-time line- and disk-light shading with linearly transformed cosines").
//
//   float ltcDiskIntegral(mat3 minv, vec3 center, vec3 axisU, vec3 axisV)
//
// The integral of the cosine lobe moved by M over the ellipse center + axisU cos t + axisV sin t
// (filled), given M^-1, normalised like ltcPolygonIntegral (ltc.glsl): the form factor of the
// moved ellipse, 1 for a shape that fills the whole upper hemisphere. All vectors are in the
// shading frame (+z the normal, the shading point at the origin): `center` relative to the
// shading point, axisU and axisV the radius-scaled in-plane axes (any two conjugate semi-
// diameters; a disk's are orthogonal and of equal length). The shape emits towards
// cross(axisU, axisV): from its other side it gives exactly 0. With M^-1 = identity it is the
// diffuse form factor.
//
// How: M^-1 moves the ellipse to another ellipse. The cone from the shading point through it is
// a quadric w^T Q w <= 0 whose eigenvectors give the cone's axis and its two half-angles, and
// an elliptic cone's form factor about its own axis has a closed form. The horizon then cuts it
// as it cuts a sphere (a spherical cap) of the same vector form factor: Snyder's clipped-sphere
// formula (sphere_irradiance.glsl). A moved ellipse wholly below the horizon gives exactly 0,
// whatever that approximation would say.
#ifndef CANDELA_LTC_DISK_GLSL
#define CANDELA_LTC_DISK_GLSL

#include "common/math.glsl"
#include "common/sphere_irradiance.glsl"

// The eigenvalues of the symmetric Q, largest first (Smith's trigonometric solution: all real).
vec3 ltcSymmetricEigenvalues(mat3 q) {
    float mean = (q[0][0] + q[1][1] + q[2][2]) / 3.0;
    mat3 k = q - mat3(mean);
    float p2 = (k[0][0] * k[0][0] + k[1][1] * k[1][1] + k[2][2] * k[2][2] +
                2.0 * (k[0][1] * k[0][1] + k[0][2] * k[0][2] + k[1][2] * k[1][2])) /
               6.0;
    float p = sqrt(max(p2, 1e-30));
    float r = clamp(determinant(k) / (2.0 * p2 * p), -1.0, 1.0);
    float phi = acos(r) / 3.0;
    float largest = mean + 2.0 * p * cos(phi);
    float smallest = mean + 2.0 * p * cos(phi + 2.0 * PI / 3.0);
    return vec3(largest, 3.0 * mean - largest - smallest, smallest);
}

// The vector form factor (direction and magnitude) of the filled ellipse center + u cos t +
// v sin t, without the horizon. Returns vec4(unit axis, form factor).
vec4 ltcEllipseVectorFormFactor(vec3 center, vec3 u, vec3 v) {
    // Principal axes: the conjugate diameters rotated by t0, where |u cos t + v sin t| is
    // extreme (tan 2 t0 = 2 u.v / (u.u - v.v)); M^-1 shears a disk's orthogonal axes.
    float uu = dot(u, u), vv = dot(v, v), uv = dot(u, v);
    float t0 = 0.5 * atan(2.0 * uv, uu - vv);
    float c = cos(t0), s = sin(t0);
    vec3 major = c * u + s * v;
    vec3 minor = c * v - s * u;
    float majorLength = length(major);
    float minorLength = length(minor);
    if (minorLength <= 0.0 || majorLength <= 0.0) return vec4(0.0);
    vec3 e1 = major / majorLength;
    vec3 n = safeNormalize(cross(major, minor));
    vec3 e2 = cross(n, e1);
    // Frame (e1, e2, n) with n towards the plane, the plane scaled to distance 1: the ellipse
    // is centred at (x0, y0, 1) with half-axes a, b (tangents of angles seen from the point).
    float distance = dot(center, n);
    if (distance < 0.0) {
        n = -n;
        e2 = -e2;
        distance = -distance;
    }
    if (distance <= 1e-7 * max(length(center), majorLength)) return vec4(0.0);  // edge-on
    float x0 = dot(center, e1) / distance;
    float y0 = dot(center, e2) / distance;
    // The cone ((x - x0 z) / a)^2 + ((y - y0 z) / b)^2 <= z^2, scaled by a^2 so every entry is
    // of the order of 1 + x0^2 (no overflow for tiny ellipses): pa = 1, qb = (a / b)^2.
    float a = majorLength / distance;
    float ratio = majorLength / minorLength;
    float pa = 1.0;
    float qb = ratio * ratio;
    float aa = a * a;
    mat3 q = mat3(pa, 0.0, -pa * x0,  //
                  0.0, qb, -qb * y0,  //
                  -pa * x0, -qb * y0, pa * x0 * x0 + qb * y0 * y0 - aa);
    vec3 e = ltcSymmetricEigenvalues(q);
    // det Q = -pa qb a^2 exactly (Q = B^-T diag(1, 1, -1) B^-1 scaled): the negative eigenvalue
    // from it keeps full precision when it is tiny next to the other two (a small ellipse).
    float negative = -pa * qb * aa / max(e.x * e.y, 1e-30);
    // Half-angle tangents^2 of the cone about its axis: -negative / e.x and -negative / e.y;
    // an elliptic cone's form factor is tan_a tan_b / sqrt((1 + tan_a^2) (1 + tan_b^2)).
    float formFactor = -negative * inversesqrt(max((e.x - negative) * (e.y - negative), 1e-30));
    // Axis: the eigenvector of the negative eigenvalue (rows 1 and 2 of (Q - e) w = 0).
    vec3 axis = vec3(pa * x0 / (pa - negative), qb * y0 / (qb - negative), 1.0);
    axis = safeNormalize(axis.x * e1 + axis.y * e2 + axis.z * n);
    return vec4(axis, formFactor);
}

float ltcDiskIntegral(mat3 minv, vec3 center, vec3 axisU, vec3 axisV) {
    // One-sided: the point must be on the emitting side (before the transform, whose
    // determinant is positive, so the side is the same after it).
    if (dot(center, cross(axisU, axisV)) >= 0.0) return 0.0;
    vec3 c = minv * center;
    vec3 u = minv * axisU;
    vec3 v = minv * axisV;
    // Highest point of the moved ellipse: nothing above the horizon, nothing received.
    if (c.z + sqrt(u.z * u.z + v.z * v.z) <= 0.0) return 0.0;
    vec4 vectorFormFactor = ltcEllipseVectorFormFactor(c, u, v);
    float sinSigmaSq = min(vectorFormFactor.w, 1.0);
    if (sinSigmaSq <= 0.0) return 0.0;
    // The cap of the same vector form factor, clipped by the horizon.
    return sphereIrradianceFactor(vectorFormFactor.z, sinSigmaSq) / PI;
}

#endif
