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
// an elliptic cone's form factor about its own axis has a closed form: its vector form factor,
// whose z is the exact integral when the moved ellipse is wholly above the horizon. Across the
// horizon, the horizon cuts it as it cuts a sphere (a spherical cap) of the same vector form
// factor: Snyder's clipped-sphere formula (sphere_irradiance.glsl), exact for a cap. An ellipse wholly below the horizon, before or after the
// move, gives exactly 0, whatever that approximation would say.
#ifndef CANDELA_LTC_DISK_GLSL
#define CANDELA_LTC_DISK_GLSL

#include "common/math.glsl"
#include "common/sphere_irradiance.glsl"

// The eigenvalues of the symmetric Q, largest first (Smith's trigonometric solution: all real;
// accurate to about eps times Q's largest eigenvalue).
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
    // Q's characteristic polynomial chi(l) = l^3 - trace l^2 + minors l - det has exact
    // coefficients: det = -qb a^2, and Q + a^2 e3 e3^T is positive semi-definite, so the one
    // negative eigenvalue lies in [-a^2, 0). The trigonometric solver alone loses it in fp32
    // when the other two are far apart (a grazing or a tiny ellipse: 20 % off, found by
    // LtcDisk.*); Newton on chi refines it. Below chi's inflection (trace / 3, above the
    // smallest root) chi is concave and rising, so the steps settle on it from the left.
    float trace = pa + qb + q[2][2];
    float minors = qb * (1.0 + x0 * x0 + y0 * y0 - aa) - aa;
    float det = -pa * qb * aa;
    // Start from the solver's eigenvalue of the largest magnitude: the negative one itself
    // when it dominates (the point close to the disk), else det over the two positive ones
    // (a small or distant ellipse). From either side of the root Newton then lands left of it.
    vec3 e = ltcSymmetricEigenvalues(q);
    float negative = -e.z > e.x ? e.z : det / max(e.x * e.y, 1e-30);
    negative = clamp(negative, -aa, 0.0);
    for (int i = 0; i < 4; ++i) {
        float chi = ((negative - trace) * negative + minors) * negative - det;
        float slope = (3.0 * negative - 2.0 * trace) * negative + minors;
        negative = clamp(negative - chi / max(slope, 1e-30), -aa, 0.0);
    }
    // (e1 - negative) (e2 - negative) = chi'(negative), and the half-angle tangents^2 of the cone
    // about its axis are -negative / e1 and -negative / e2: an elliptic cone's form factor,
    // tan_a tan_b / sqrt((1 + tan_a^2) (1 + tan_b^2)), is -negative / sqrt(chi'(negative)).
    float slope = (3.0 * negative - 2.0 * trace) * negative + minors;
    float formFactor = -negative * inversesqrt(max(slope, 1e-30));
    // Axis: the eigenvector of the negative eigenvalue (rows 1 and 2 of (Q - e) w = 0).
    vec3 axis = vec3(pa * x0 / (pa - negative), qb * y0 / (qb - negative), 1.0);
    axis = safeNormalize(axis.x * e1 + axis.y * e2 + axis.z * n);
    return vec4(axis, formFactor);
}

float ltcDiskIntegral(mat3 minv, vec3 center, vec3 axisU, vec3 axisV) {
    // One-sided: the point must be on the emitting side (before the transform, whose
    // determinant is positive, so the side is the same after it).
    if (dot(center, cross(axisU, axisV)) >= 0.0) return 0.0;
    // Wholly below the surface's horizon: nothing, whatever part of the moved cosine lies
    // there (M^-1 can lift directions under the horizon above the moved one).
    if (center.z + sqrt(axisU.z * axisU.z + axisV.z * axisV.z) <= 0.0) return 0.0;
    vec3 c = minv * center;
    vec3 u = minv * axisU;
    vec3 v = minv * axisV;
    float reach = sqrt(u.z * u.z + v.z * v.z);  // how far the moved ellipse rises above c.z
    if (c.z + reach <= 0.0) return 0.0;
    vec4 vectorFormFactor = ltcEllipseVectorFormFactor(c, u, v);
    float formFactor = min(vectorFormFactor.w, 1.0);
    if (formFactor <= 0.0) return 0.0;
    float z = vectorFormFactor.z;
    // Wholly above the moved horizon: the vector form factor's z is the exact integral.
    if (c.z - reach >= 0.0) return formFactor * z;
    // Across it: the cap of the same vector form factor (angular radius sigma), placed so that
    // the same fraction of its height as of the ellipse's (by elevation of its highest and
    // lowest points) is above the horizon, cut there by Snyder's formula; plus that fraction of
    // the unclipped difference, so the result meets the exact one when the ellipse rises
    // wholly above the horizon and 0 when it sinks below. A cap (the sphere light's disk) is
    // placed where it is: exact.
    vec3 rise = (u * u.z + v * v.z) / reach;
    float highest = asin(clamp((c.z + reach) / length(c + rise), -1.0, 1.0));
    float lowest = asin(clamp((c.z - reach) / length(c - rise), -1.0, 1.0));
    float above = saturate(highest / max(highest - lowest, 1e-12));
    float sigma = asin(sqrt(formFactor));
    float placed = sin(sigma * (2.0 * above - 1.0));
    float clipped = sphereIrradianceFactor(placed, formFactor) / PI + above * formFactor * (z - placed);
    return max(clipped, 0.0);
}

#endif
