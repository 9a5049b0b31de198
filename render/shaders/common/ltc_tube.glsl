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
// Seen from any direction the capsule's silhouette is the cylinder's (width 2 r, projected
// length l sin phi, phi the angle to the axis) plus a disk of pi r^2 shared by the caps.
//   Thin (r under 1e-3 of the nearest end's distance): L 2 r l ltcCylinderIntegral, Heitz and
//   Hill 2017's Lambertian line, one closed form and no loop; caps and width add under 1e-3.
//   Thick: the rectangle through the axis facing the point (ltcPolygonIntegral), as wide as the
//   cylinder's silhouette (the angle 2 asin(r / h), h the distance to the axis) and run on
//   pi r / 4 past each end, where each cap shows a half-disk of pi r^2 / 2 seen across the axis.
//   Seen along the axis (phi -> 0) the caps' share is undercounted (pi r^2 sin phi for pi r^2).
// Measured: report "area lights by LTC", capsule rows; LtcTube.* in render_stability_tests.
#ifndef CANDELA_LTC_TUBE_GLSL
#define CANDELA_LTC_TUBE_GLSL

#include "common/ltc.glsl"
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
    // The caps: a cap's silhouette beyond its end is a half-disk, area pi r^2 / 2 (seen across
    // the axis): the rectangle runs on pi r / 4 past each end, the same area at the same place.
    // (Whole disks facing the point at the ends, weighted by each cap's share, overlapped the
    // rectangle: a 0.25 m tube of radius 0.3 m came out 70 % too bright at roughness 0.1.)
    vec3 extension = axis * (0.25 * PI * r);
    vec3 q0 = p0 - extension, q1 = p1 + extension;
    // Clockwise as seen from the point (ltcPolygonIntegral's lit side).
    vec3 quad[4] = vec3[4](q0 + across, q1 + across, q1 - across, q0 - across);
    float integral = ltcPolygonIntegral(minv, quad, 4);
    return luminance * integral;
}

#endif
