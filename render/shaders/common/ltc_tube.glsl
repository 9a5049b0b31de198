// A tube light of radius r and length l as the Lambertian capsule it is (issue 15, "tubes: a
// line plus end caps"), by linearly transformed cosines:
//
//   float ltcTubeIntegral(mat3 minv, vec3 p0, vec3 p1, float radius)
//
// returns the unit-magnitude lobe's integral over the capsule around the segment p0..p1
// (shading frame, relative to the shading point) per candela of the engine's tube intensity I.
// The engine gives a tube I = lumens / (4 pi) (gpu_light.cpp); a Lambertian capsule of those
// lumens has luminance L = 4 pi I / (pi A) = 4 I / A, A = 2 pi r l + 4 pi r^2.
//
// Seen from any direction the capsule's silhouette is the cylinder's (width 2 r, length
// l sin phi, phi the angle to the axis) plus a disk of pi r^2 shared by the caps: the cap
// pointing towards the point shows (pi r^2 / 2)(1 + |cos phi|), the other (pi r^2 / 2)
// (1 - |cos phi|). So
//   cylinder: thin (r under 1e-3 of the nearest end's distance): L 2 r l ltcCylinderIntegral,
//             Heitz and Hill 2017's Lambertian line, one closed form and no loop; thick: the
//             rectangle through the axis facing the point (ltcPolygonIntegral), as wide as the
//             cylinder's silhouette (2 r l sin phi projected, the angle 2 asin(r / h));
//   caps:     (thick only) each cap's share of the sphere of radius r at its end, integrated as
//             the disk facing the point (ltcSphereIntegral, as sphere lights are).
// A thin tube's caps and width add under 1e-3 relative; the thin path is the one most scenes
// take. Measured: report "area lights by LTC", capsule rows; LtcTube.* in render_stability_tests.
#ifndef CANDELA_LTC_TUBE_GLSL
#define CANDELA_LTC_TUBE_GLSL

#include "common/ltc.glsl"
#include "common/ltc_area_lights.glsl"
#include "common/ltc_line.glsl"
#include "common/math.glsl"

float ltcTubeIntegral(mat3 minv, vec3 p0, vec3 p1, float radius) {
    vec3 d = p1 - p0;
    float len = length(d);
    float r = max(radius, 0.0);
    float nearestSq = min(dot(p0, p0), dot(p1, p1));
    if (!(r * r > 1e-6 * nearestSq)) {
        // L 2 r l per candela = 8 r l / (2 pi r l + 4 pi r^2) = 4 l / (pi (l + 2 r)), 4 / pi at
        // radius 0: a thin Lambertian tube is 4 / pi brighter across its axis than the isotropic
        // line of the same lumens, and dimmer along it.
        return 4.0 * len / (PI * max(len + 2.0 * r, 1e-30)) * ltcCylinderIntegral(minv, p0, p1);
    }
    float luminance = 4.0 / (PI * r * (2.0 * len + 4.0 * r));  // 4 / A per candela
    vec3 axis = d / max(len, 1e-30);
    // |across| = h, the distance to the axis line. The half-width r h / sqrt(h^2 - r^2) makes the
    // rectangle subtend the cylinder's angle 2 asin(r / h) (as the sphere's disk does).
    vec3 across = cross(axis, p0 + 0.5 * d);
    float h = length(across);
    float halfWidth = r * inversesqrt(max(1.0 - r * r / max(h * h, 1e-30), 1e-4));
    across = h > 0.0 ? across * (halfWidth / h) : tangentFrame(axis)[0] * r;
    // Clockwise as seen from the point (ltcPolygonIntegral's lit side).
    vec3 quad[4] = vec3[4](p0 + across, p1 + across, p1 - across, p0 - across);
    float integral = ltcPolygonIntegral(minv, quad, 4);
    // The cap at p0 points along -axis and faces the point when p0 . axis > 0.
    float share0 = 0.5 * (1.0 + dot(axis, p0) / max(length(p0), 1e-30));
    float share1 = 0.5 * (1.0 - dot(axis, p1) / max(length(p1), 1e-30));
    integral += share0 * ltcSphereIntegral(minv, p0, r) + share1 * ltcSphereIntegral(minv, p1, r);
    return luminance * integral;
}

#endif
