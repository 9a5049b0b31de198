#pragma once
// Double-precision specular of a sphere and of a segment (tube of radius 0) light, integrated
// over the light: the surface is at the origin with N = +Z, F0 = 1 (Fresnel 1), the BRDF is
// the lighting pass's D (eq. 3) and Vis (eq. 4), intensity 1 cd.
#include <cmath>
#include <numbers>

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

// D Vis NoL toward unit direction L.
inline double specularTimesNoL(const Vec3& V, const Vec3& L, double alpha) {
    namespace ref = stability::reference;
    const double NoL = L[2], NoV = V[2];
    if (NoL <= 0.0 || NoV <= 0.0) return 0.0;
    const Vec3 H = normalized(V + L);
    return ref::ggxDistribution(alpha, H[2]) * ref::smithSchlickVisibility(alpha, NoV, NoL) * NoL;
}

// Sphere of radius r around `centre`, luminance I / (pi r^2): midpoint quadrature over the
// cone it subtends, direction = cos(psi) c + sin(psi) (cos(phi) u + sin(phi) w),
// d(solid angle) = sin(psi) dpsi dphi, n x n points.
inline double sphereSpecularReference(const Vec3& centre, double radius, const Vec3& V,
                                      double alpha, int n) {
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
            ring += specularTimesNoL(V, L, alpha);
        }
        sum += ring * sinPsi;
    }
    return luminance * sum * dpsi * dphi;
}

// Segment from centre - axis l / 2 to centre + axis l / 2, intensity spread evenly along it
// (as lineIrradiance assumes): the mean over n midpoints of a point light's specular,
// with the engine's 1 / (d^2 + 1e-4) falloff.
inline double tubeSpecularReference(const Vec3& centre, const Vec3& axis, double length,
                                    const Vec3& V, double alpha, int n) {
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const Vec3 P = centre + ((((i + 0.5) / n) - 0.5) * length) * axis;
        const double distanceSq = stability::reference::dot(P, P);
        sum += specularTimesNoL(V, normalized(P), alpha) *
               stability::reference::inverseSquare(std::sqrt(distanceSq));
    }
    return sum / n;
}

}  // namespace candela::report
