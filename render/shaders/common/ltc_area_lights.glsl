// Sphere and tube lights by linearly transformed cosines (issue 15, --area-lights ltc): the
// shading frame the LTC table is fitted in, the sphere as the disk facing the shading point
// that subtends the same cone (ltc_disk.glsl), the tube as a segment (ltc_line.glsl).
// The results are lobe integrals of a unit-magnitude LTC; the caller multiplies by the table's
// magnitude (and Fresnel) and by the light's luminance (sphere) or intensity (tube).
#ifndef CANDELA_LTC_AREA_LIGHTS_GLSL
#define CANDELA_LTC_AREA_LIGHTS_GLSL

#include "common/ltc_disk.glsl"
#include "common/ltc_line.glsl"
#include "common/math.glsl"

// Rows: the frame the table is fitted in (N = +z, V in the xz-plane with x >= 0); frame * w
// takes a world vector into it. V along N picks any tangent.
mat3 ltcShadingFrame(vec3 N, vec3 V) {
    vec3 t = V - N * dot(N, V);
    float lengthSq = dot(t, t);
    vec3 t1 = lengthSq > 1e-12 ? t * inversesqrt(lengthSq) : tangentFrame(N)[0];
    vec3 t2 = cross(N, t1);
    return transpose(mat3(t1, t2, N));
}

// M^-1 from the table's four entries (00, 02, 20, 22; 11 = 1).
mat3 ltcInverseMatrix(vec4 entries) {
    return mat3(vec3(entries.x, 0.0, entries.z), vec3(0.0, 1.0, 0.0), vec3(entries.y, 0.0, entries.w));
}

// The LTC integral over a sphere of radius `radius` around `center` (shading frame, relative to
// the shading point): the disk through its centre, facing the point, with the same angular
// radius sigma (tan sigma = radius tan / distance). Inside the sphere the cone is capped just
// short of a hemisphere.
float ltcSphereIntegral(mat3 minv, vec3 center, float radius) {
    float distance = length(center);
    if (distance <= 0.0) return 0.0;
    float sinSigma = min(radius / distance, 0.9999);
    float diskRadius = distance * sinSigma * inversesqrt(1.0 - sinSigma * sinSigma);
    vec3 toward = -center / distance;  // the disk's lit side faces the point
    mat3 frame = tangentFrame(toward);  // columns t, b, toward with t x b = toward
    return ltcDiskIntegral(minv, center, frame[0] * diskRadius, frame[1] * diskRadius);
}

#endif
