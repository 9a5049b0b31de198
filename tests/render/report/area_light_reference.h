#pragma once
// Double-precision specular of a sphere and of a segment (tube of radius 0) light, integrated
// over the light: the surface is at the origin with N = +Z, F0 = 1 (Fresnel 1), the BRDF is
// the lighting pass's D (eq. 3) and Vis (eq. 4), intensity 1 cd.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "../stability/brdf_reference.h"
#include "../stability/light_reference.h"

namespace candela::report {

using stability::reference::Vec3;
using stability::reference::operator+;
using stability::reference::operator-;
using stability::reference::operator*;

inline Vec3 normalized(const Vec3& v) {
    return (1.0 / stability::reference::length(v)) * v;
}

// D Vis NoL toward unit direction L; Vis is Karis 2013's ("Real Shading in Unreal Engine 4")
// Schlick-Smith, or with `correlated` the energy-conserving BRDF's height-correlated Smith (the
// lobe the LTC table is fitted to).
inline double specularTimesNoL(const Vec3& V, const Vec3& L, double alpha,
                               bool correlated = false) {
    namespace ref = stability::reference;
    const double NoL = L[2], NoV = V[2];
    if (NoL <= 0.0 || NoV <= 0.0) return 0.0;
    const Vec3 H = normalized(V + L);
    const double visibility = correlated ? ref::smithGgxCorrelatedVisibility(alpha, NoV, NoL)
                                         : ref::smithSchlickVisibility(alpha, NoV, NoL);
    return ref::ggxDistribution(alpha, H[2]) * visibility * NoL;
}

// Sphere of radius r around `centre`, luminance I / (pi r^2): midpoint quadrature over the
// cone it subtends, direction = cos(psi) c + sin(psi) (cos(phi) u + sin(phi) w),
// d(solid angle) = sin(psi) dpsi dphi, n x n points.
inline double sphereSpecularReference(const Vec3& centre, double radius, const Vec3& V,
                                      double alpha, int n, bool correlated = false) {
    constexpr double kPi = std::numbers::pi;
    const double distance = stability::reference::length(centre);
    const Vec3 c = (1.0 / distance) * centre;
    const double sigma = std::asin(std::min(radius / distance, 1.0));
    // u, w: an orthonormal pair perpendicular to c.
    const Vec3 helper = std::fabs(c[2]) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
    const Vec3 u = normalized(helper - stability::reference::dot(helper, c) * c);
    const Vec3 w = {c[1] * u[2] - c[2] * u[1], c[2] * u[0] - c[0] * u[2],
                    c[0] * u[1] - c[1] * u[0]};
    const double luminance = 1.0 / (kPi * radius * radius);
    const double dpsi = sigma / n, dphi = 2.0 * kPi / n;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const double psi = (i + 0.5) * dpsi;
        const double sinPsi = std::sin(psi), cosPsi = std::cos(psi);
        double ring = 0.0;
        for (int j = 0; j < n; ++j) {
            const double phi = (j + 0.5) * dphi;
            const Vec3 L = cosPsi * c + (sinPsi * std::cos(phi)) * u + (sinPsi * std::sin(phi)) * w;
            ring += specularTimesNoL(V, L, alpha, correlated);
        }
        sum += ring * sinPsi;
    }
    return luminance * sum * dpsi * dphi;
}

// Segment from centre - axis l / 2 to centre + axis l / 2, intensity spread evenly along it
// (as lineIrradiance assumes): the mean over n midpoints of a point light's specular,
// with the engine's 1 / (d^2 + 1e-4) falloff.
inline double tubeSpecularReference(const Vec3& centre, const Vec3& axis, double length,
                                    const Vec3& V, double alpha, int n, bool correlated = false) {
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const Vec3 P = centre + ((((i + 0.5) / n) - 0.5) * length) * axis;
        const double distanceSq = stability::reference::dot(P, P);
        sum += specularTimesNoL(V, normalized(P), alpha, correlated) *
               stability::reference::inverseSquare(std::sqrt(distanceSq));
    }
    return sum / n;
}

// The Lambertian capsule a tube light of radius r is (issue 15): a cylinder of radius r around
// the segment centre +- axis l / 2 and two hemispherical end caps, emitting the engine's tube
// lumens (4 pi I, gpu_light.cpp: I = lumens / (4 pi)) evenly over its area A = 2 pi r l +
// 4 pi r^2: luminance 4 I / A, I = 1 cd. Midpoint quadrature over the surface, about `spacing`
// metres between points, at least 64 around (cylinder: along x around; caps: cos theta x
// around, equal areas), each
// element counted where it faces the shading point (the capsule is convex: nothing else hides
// it), with the exact 1 / d^2: the integral over the capsule's cone of lobe(L) L dw.
template <class Lobe>
double capsuleIntegral(const Vec3& centre, const Vec3& axis, double length, double radius,
                       double spacing, const Lobe& lobe) {
    namespace ref = stability::reference;
    constexpr double kPi = std::numbers::pi;
    const Vec3 helper = std::fabs(axis[2]) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
    const Vec3 e1 = normalized(helper - ref::dot(helper, axis) * axis);
    const Vec3 e2 = {axis[1] * e1[2] - axis[2] * e1[1], axis[2] * e1[0] - axis[0] * e1[2],
                     axis[0] * e1[1] - axis[1] * e1[0]};
    const double luminance = 4.0 / (2.0 * kPi * radius * length + 4.0 * kPi * radius * radius);
    auto element = [&](const Vec3& X, const Vec3& normal, double area) {
        const double distanceSq = ref::dot(X, X);
        const Vec3 L = (1.0 / std::sqrt(distanceSq)) * X;
        const double emitted = -ref::dot(normal, L);
        if (emitted <= 0.0) return 0.0;
        return lobe(L) * emitted * area / distanceSq;
    };
    // At least 64 around: 8 midpoints of the clamped cosine around a thin cylinder came out 2.6 %
    // too bright (the report's radius 0.02 m rows at 2 cm spacing).
    const int around = std::max(64, int(std::ceil(2.0 * kPi * radius / spacing)));
    const int along = std::max(1, int(std::ceil(length / spacing)));
    const double dpsi = 2.0 * kPi / around;
    double sum = 0.0;
    for (int j = 0; j < around; ++j) {
        const double psi = (j + 0.5) * dpsi;
        const Vec3 normal = std::cos(psi) * e1 + std::sin(psi) * e2;
        for (int i = 0; i < along; ++i) {
            const Vec3 X = centre + ((((i + 0.5) / along) - 0.5) * length) * axis + radius * normal;
            sum += element(X, normal, (length / along) * radius * dpsi);
        }
    }
    // Caps: z = cos theta uniform in [0, 1] gives equal areas r^2 dz dpsi.
    const int rings = std::max(16, int(std::ceil(0.5 * kPi * radius / spacing)));
    for (double side : {-1.0, 1.0}) {
        const Vec3 end = centre + (0.5 * length * side) * axis;
        for (int k = 0; k < rings; ++k) {
            const double z = (k + 0.5) / rings;
            const double rho = std::sqrt(1.0 - z * z);
            for (int j = 0; j < around; ++j) {
                const double psi = (j + 0.5) * dpsi;
                const Vec3 normal =
                    (side * z) * axis + (rho * std::cos(psi)) * e1 + (rho * std::sin(psi)) * e2;
                sum += element(end + radius * normal, normal, radius * radius * dpsi / rings);
            }
        }
    }
    return luminance * sum;
}

// The capsule's specular D Vis NoL (F0 = 1) for view V.
inline double capsuleSpecularReference(const Vec3& centre, const Vec3& axis, double length,
                                       double radius, const Vec3& V, double alpha, double spacing,
                                       bool correlated = true) {
    return capsuleIntegral(centre, axis, length, radius, spacing, [&](const Vec3& L) {
        return specularTimesNoL(V, L, alpha, correlated);
    });
}

// The capsule's irradiance on the surface (N = +Z): lux per candela of the tube.
inline double capsuleIrradianceReference(const Vec3& centre, const Vec3& axis, double length,
                                         double radius, double spacing) {
    return capsuleIntegral(centre, axis, length, radius, spacing,
                           [](const Vec3& L) { return std::max(L[2], 0.0); });
}

// The report's area-light geometry (area_light_rows.cpp, ltc_area_light_rows.cpp): the light's
// centre 1 m away, 30 degrees from the normal; a tube's axis out of the plane of incidence.
inline constexpr double kLightElevation = std::numbers::pi / 6.0;
inline const Vec3 kLightCentre = {std::sin(kLightElevation), 0.0, std::cos(kLightElevation)};
inline const Vec3 kLightAcross = {std::cos(kLightElevation), 0.0, -std::sin(kLightElevation)};
inline const Vec3 kLightAlong = {0.0, 1.0, 0.0};
inline constexpr double kAreaLightRoughness[] = {0.1, 0.25, 0.5, 0.75, 1.0};

// A view whose mirror direction R leaves the light centre by `across` and `along` radians.
struct AreaLightView {
    double across, along;
};

inline Vec3 viewFor(const AreaLightView& g) {
    const Vec3 R = normalized(kLightCentre + std::tan(g.across) * kLightAcross +
                              std::tan(g.along) * kLightAlong);
    return {-R[0], -R[1], R[2]};  // reflect R about N = +Z
}

// Sphere of sin(sigma) s: R through the centre, half-way to the rim, at the rim, outside it
// (2 sigma) in the plane of incidence, and 0.5 and 1.5 sigma across it.
inline std::vector<AreaLightView> sphereViews(double s) {
    const double sigma = std::asin(s);
    return {{0, 0},         {0.5 * sigma, 0}, {sigma, 0},
            {2 * sigma, 0}, {0, 0.5 * sigma}, {0, 1.5 * sigma}};
}

// Tube of `length` m: R through the centre, along the axis to 0.5, 1 and 1.5 half-lengths, and
// 0.1 rad across it at 0 and 0.5 half-lengths.
inline std::vector<AreaLightView> tubeViews(double length) {
    const double half = std::atan(0.5 * length);
    return {{0, 0}, {0, 0.5 * half}, {0, half}, {0, 1.5 * half}, {0.1, 0}, {0.1, 0.5 * half}};
}

}  // namespace candela::report
