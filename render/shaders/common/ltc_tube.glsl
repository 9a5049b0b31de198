// A tube light of radius r and length l as the Lambertian capsule it is (issue 15, "tubes: a
// line plus end caps"), by linearly transformed cosines:
//
//   vec2 ltcTubeIntegrals(mat3 minv, vec3 p0, vec3 p1, float radius)
//
// returns, per candela of the engine's tube intensity I, (the unit-magnitude lobe's integral
// over the capsule around the segment p0..p1, the same integral with M^-1 = identity: the
// capsule's form factor). Vectors in the shading frame (+z the normal), relative to the shading
// point; the diffuse irradiance per candela is pi times the second. ltcTubeIntegral is the first.
// The engine gives a tube I = lumens / (4 pi) (gpu_light.cpp); a Lambertian capsule of those
// lumens has luminance L = 4 pi I / (pi A) = 4 I / A, A = 2 pi r l + 4 pi r^2.
//
// A capsule is the union of the spheres of radius r along the segment, so the cone it fills seen
// from a point outside the cylinder around the axis is the convex hull of its two end spheres'
// cones: the two planes through the point tangent to the cylinder bound it along the axis (two
// great-circle edges, exact), each end sphere's cone beyond its tangent points closes it (an arc
// of a small circle, drawn as kLtcTubeArcSegments great-circle chords in all, shared by the two
// arcs by their angles, the inner vertices pushed out so each arc's polygon keeps the circle
// segment's area). From inside that cylinder the nearer end sphere hides the rest: its cone
// alone (ltcSphereIntegral). Thin tubes (r under 1e-3 of the nearest end's distance):
// L 2 r l ltcCylinderIntegral, Heitz and Hill 2017's Lambertian line in closed form; caps and
// width add under 1e-3.
// Measured: report "area lights by LTC", capsule rows; LtcTube.* in render_stability_tests.
#ifndef CANDELA_LTC_TUBE_GLSL
#define CANDELA_LTC_TUBE_GLSL

#include "common/brdf.glsl"
#include "common/ltc.glsl"
#include "common/ltc_area_lights.glsl"
#include "common/ltc_line.glsl"
#include "common/math.glsl"

// Chords drawing the two caps' arcs together; the outline has kLtcTubeArcSegments + 2 vertices.
const int kLtcTubeArcSegments = 6;
const int kLtcTubeOutlineVertices = kLtcTubeArcSegments + 2;

// The integral of the cosine moved by M over a convex spherical polygon (vertices relative to
// the point, in order as ltcPolygonIntegral winds them), clipped edge by edge to the moved
// horizon: a convex polygon leaves it at most once and comes back once, so the clipped outline
// is its edges' parts above plus one horizon edge from the exit to the entry. No clipped copy.
float ltcTubeOutlineIntegral(mat3 minv, vec3 outline[kLtcTubeOutlineVertices]) {
    float sum = 0.0;
    vec3 exitPoint = vec3(0.0), entryPoint = vec3(0.0);
    bool crossed = false;
    vec3 a = minv * outline[kLtcTubeOutlineVertices - 1];
    for (int i = 0; i < kLtcTubeOutlineVertices; ++i) {
        vec3 b = minv * outline[i];
        if (a.z >= 0.0 && b.z >= 0.0) {
            sum += ltcEdgeIntegral(safeNormalize(a), safeNormalize(b));
        } else if (a.z >= 0.0 || b.z >= 0.0) {
            vec3 horizon = safeNormalize(mix(a, b, a.z / (a.z - b.z)));
            crossed = true;
            if (a.z >= 0.0) {
                sum += ltcEdgeIntegral(safeNormalize(a), horizon);
                exitPoint = horizon;
            } else {
                sum += ltcEdgeIntegral(horizon, safeNormalize(b));
                entryPoint = horizon;
            }
        }
        a = b;
    }
    if (crossed) sum += ltcEdgeIntegral(exitPoint, entryPoint);
    return max(sum * (0.5 / PI), 0.0);
}

vec2 ltcTubeIntegrals(mat3 minv, vec3 p0, vec3 p1, float radius) {
    vec3 d = p1 - p0;
    float len = length(d);
    float r = max(radius, 0.0);
    float nearestSq = min(dot(p0, p0), dot(p1, p1));
    if (!(r * r > 1e-6 * nearestSq)) {
        // L 2 r l per candela = 8 r l / (2 pi r l + 4 pi r^2) = 4 l / (pi (l + 2 r)), 4 / pi at
        // radius 0: a thin Lambertian tube is 4 / pi brighter across its axis than the isotropic
        // line of the same lumens, and dimmer along it.
        float scale = 4.0 * len / (PI * max(len + 2.0 * r, 1e-30));
        vec2 cylinder =
            scale * vec2(ltcCylinderIntegral(minv, p0, p1), ltcCylinderIntegral(mat3(1.0), p0, p1));
        // The caps add pi r^2 to the silhouette's 2 r l sin(phi): nothing across the axis, all of
        // it end-on, where the cylinder shows nothing. As a disk at the nearer end, of solid
        // angle pi r^2 / d^2 times the lobe there: D_o(w) = max((M^-1 w).z, 0) |det M^-1| /
        // (pi |M^-1 w|^4) (Heitz et al. 2016, eq. 1), the cosine's max(w.z, 0) / pi for M = I.
        vec3 nearer = dot(p0, p0) < dot(p1, p1) ? p0 : p1;
        vec3 w = nearer * inversesqrt(max(nearestSq, 1e-30));
        vec3 moved = minv * w;
        float movedSq = dot(moved, moved);
        float lobe =
            w.z > 0.0 ? max(moved.z, 0.0) * abs(determinant(minv)) / (PI * movedSq * movedSq) : 0.0;
        float caps = 4.0 * r / ((2.0 * len + 4.0 * r) * max(nearestSq, 1e-30));  // L pi r^2 / d^2
        return cylinder + caps * vec2(lobe, max(w.z, 0.0) / PI);
    }
    float luminance = 4.0 / (PI * r * (2.0 * len + 4.0 * r));  // 4 / A per candela
    vec3 axis = d / max(len, 1e-30);
    // q: from the point to the axis line, h = |q|; t0, t1: the ends along the axis from its foot.
    float t0 = dot(p0, axis), t1 = dot(p1, axis);
    vec3 q = p0 - t0 * axis;
    float h = length(q);
    if (!(h > 1.0001 * r)) {
        // Inside the cylinder around the axis (or inside the capsule: anything finite).
        vec3 nearer = abs(t0) < abs(t1) ? p0 : p1;
        return luminance *
               vec2(ltcSphereIntegral(minv, nearer, r), ltcSphereIntegral(mat3(1.0), nearer, r));
    }
    vec3 qUnit = q / h;
    vec3 across = cross(axis, qUnit);  // the tangent planes touch the cylinder at +- across
    // Each end sphere's cone is the disk of radius R = r d / sqrt(d^2 - r^2) around p facing the
    // point; its outer arc runs from the tangent point at -across through o (away from the other
    // end) to the one at +across, half-angle beta: cos beta = +- r t / (h sqrt(h^2 + t^2 - r^2)).
    float d0 = length(p0), d1 = length(p1);
    float tangent0 = sqrt(max(d0 * d0 - r * r, 1e-30)), tangent1 = sqrt(max(d1 * d1 - r * r, 1e-30));
    float beta0 = acos(clamp(-r * t0 / (h * tangent0), -1.0, 1.0));
    float beta1 = acos(clamp(r * t1 / (h * tangent1), -1.0, 1.0));
    vec3 out0 = (t0 * qUnit - h * axis) / d0;
    vec3 out1 = (h * axis - t1 * qUnit) / d1;
    float disk0 = r * d0 / tangent0, disk1 = r * d1 / tangent1;
    // The chords shared by angle (a cap seen from near its end shows most of its circle).
    int segments1 = clamp(int(round(float(kLtcTubeArcSegments) * beta1 / max(beta0 + beta1, 1e-30))), 1,
                          kLtcTubeArcSegments - 1);
    int segments0 = kLtcTubeArcSegments - segments1;
    // Inner vertices of k chords of angle delta at rho R: the fan's area
    // R^2 sin(delta) (2 rho + (k - 2) rho^2) / 2 equals the arc's sector, R^2 k delta / 2.
    vec2 step = 2.0 * vec2(beta0, beta1) / vec2(float(segments0), float(segments1));
    vec2 k = vec2(float(segments0), float(segments1));
    vec2 ratio = k * step / max(sin(step), vec2(1e-30));
    vec2 rho = mix(0.5 * ratio, (sqrt(1.0 + (k - 2.0) * ratio) - 1.0) / max(k - 2.0, vec2(1e-30)),
                   greaterThan(k, vec2(2.5)));
    // Clockwise from the point (ltcPolygonIntegral's lit side): cap 1's arc from +across to
    // -across, the -across edge back to cap 0, its arc to +across, the +across edge to cap 1.
    vec3 outline[kLtcTubeOutlineVertices];
    for (int i = 0; i < kLtcTubeOutlineVertices; ++i) {
        bool first = i <= segments1;
        int j = first ? i : i - segments1 - 1;
        int count = first ? segments1 : segments0;
        float angle = first ? beta1 - float(j) * step.y : -beta0 + float(j) * step.x;
        float scale = (j == 0 || j == count) ? 1.0 : (first ? rho.y : rho.x);
        vec3 centre = first ? p1 : p0;
        vec3 outward = first ? out1 : out0;
        float diskRadius = first ? disk1 : disk0;
        outline[i] = centre + (scale * diskRadius) * (cos(angle) * outward + sin(angle) * across);
    }
    return luminance *
           vec2(ltcTubeOutlineIntegral(minv, outline), ltcTubeOutlineIntegral(mat3(1.0), outline));
}

float ltcTubeIntegral(mat3 minv, vec3 p0, vec3 p1, float radius) {
    return ltcTubeIntegrals(minv, p0, p1, radius).x;
}

// The fitted cosine's shape error along the tube, divided out. The LTC integral is exact in the
// lobe's total (the table's magnitude) but not in how the lobe spreads it: at roughness 1 the
// lobe D Vis NoL = NoL / (2 pi (NoL + NoV)) depends on NoL alone and the fitted cosine runs
// 4 % above it at the normal, 4 % under it at 50 degrees and 12 % above at 80 (render/ltc/), so
// a tube of 2 m at 1 m, lying across 30..52 degrees, came out 2.5 % bright in every view. The
// integral is the LTC's times the ratio r = lobe / (magnitude x LTC) averaged over the light
// with the LTC's weight; r is smooth where the lobe is wide, so three Gauss-Legendre points
// along the axis (weight 1 / d^3: the thin Lambertian cylinder's lobe integrand sin(phi) / d^2)
// give that mean: sum(w lobe) / (magnitude sum(w LTC)). Narrow lobes (roughness under 0.2) fall
// between the points and are fitted closely (report: 0.1..0.5 % there), so the factor fades in
// from roughness 0.2 to 0.4. V in the shading frame; alpha = roughness^2 (brdf.glsl); the
// factor multiplies ltcTubeIntegral's result. Measured: report "area lights by LTC", capsule
// rows: worst cell 2.5 / 2.6 / 2.6 % -> 0.99 / 0.91 / 1.07 % at radius 0.02 / 0.1 / 0.3 m (mean
// 0.7 / 0.8 / 0.7 % -> 0.2 / 0.3 / 0.3 %), 145x -> 151x a point light's specular;
// LtcTube.ThickTubeMatchesTheLambertianCapsule (worst 1.66 % -> 1.34 %).
float ltcTubeLobeCorrection(mat3 minv, float magnitude, float alpha, vec3 V, vec3 p0, vec3 p1) {
    float weight = saturate((sqrt(alpha) - 0.2) / 0.2);
    if (!(weight > 0.0) || !(magnitude > 0.0)) return 1.0;
    const vec3 kPoints = vec3(0.5 - 0.5 * sqrt(0.6), 0.5, 0.5 + 0.5 * sqrt(0.6));
    const vec3 kWeights = vec3(5.0, 8.0, 5.0);
    float detInverse = abs(determinant(minv));
    float a2 = alpha * alpha;
    float NoV = saturate(V.z);
    float lobeSum = 0.0, ltcSum = 0.0;
    for (int i = 0; i < 3; ++i) {
        vec3 p = mix(p0, p1, kPoints[i]);
        float distanceSq = dot(p, p);
        vec3 L = p * inversesqrt(max(distanceSq, 1e-30));
        if (!(L.z > 0.0)) continue;
        float w = kWeights[i] * inversesqrt(max(distanceSq, 1e-30)) / max(distanceSq, 1e-30);
        vec3 moved = minv * L;
        float movedSq = dot(moved, moved);
        // Heitz et al. 2016, eq. 1, for unit L: D_o(M^-1 L / |M^-1 L|) |det M^-1| / |M^-1 L|^3.
        ltcSum += w * max(moved.z, 0.0) * detInverse / (PI * movedSq * movedSq);
        float NoH = saturate(safeNormalize(V + L).z);
        lobeSum += w * distributionGgx(a2, NoH) * visibilitySmithGgxCorrelated(alpha, NoV, L.z) * L.z;
    }
    if (!(ltcSum > 0.0)) return 1.0;
    // Trusted only where the three points integrate the LTC itself along the axis: its exact
    // integral (ltcCylinderIntegral: the mean of D h / d^3 over t) against their estimate. A lobe
    // whose peak falls between the points (a glossy sphere beside a 4 m tube in the golden
    // sphere_grid_tube_light) is off by far more than 10 % there, and keeps the plain LTC.
    vec3 pxd = cross(p0, p1 - p0);
    float h = sqrt(dot(pxd, pxd) / max(dot(p1 - p0, p1 - p0), 1e-30));
    float exact = ltcCylinderIntegral(minv, p0, p1);
    float estimate = h * ltcSum / 18.0;  // the Gauss weights sum to 18 over t in [0, 1]
    weight *= saturate(1.0 - abs(estimate / max(exact, 1e-30) - 1.0) / 0.1);
    return mix(1.0, clamp(lobeSum / (magnitude * ltcSum), 0.5, 2.0), weight);
}

#endif
