#pragma once
// Double-precision reference of the light incidence terms of Karis 2013, "Real Shading in Unreal
// Engine 4", "Lighting Model" (eq. 9-20), plus numerical integrations of what the closed forms
// stand for: the irradiance of a uniformly emitting sphere (partly below the horizon too) and of a
// uniformly emitting segment.
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numbers>

namespace candela::stability::reference {

using Vec3 = std::array<double, 3>;

inline double dot(const Vec3& a, const Vec3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline double length(const Vec3& a) {
    return std::sqrt(dot(a, a));
}
inline Vec3 operator+(const Vec3& a, const Vec3& b) {
    return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
inline Vec3 operator-(const Vec3& a, const Vec3& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline Vec3 operator*(double s, const Vec3& a) {
    return {s * a[0], s * a[1], s * a[2]};
}

// The "+1" of eq. 9 in metres (1 cm^2), as lights.glsl documents.
constexpr double kFalloffBias = 1e-4;

// eq. 9 numerator: saturate(1 - (d / r)^4)^2.
inline double attenuationWindow(double distance, double radius) {
    const double ratio = distance / radius;
    const double w = std::clamp(1.0 - std::pow(ratio, 4.0), 0.0, 1.0);
    return w * w;
}

// eq. 9 denominator.
inline double inverseSquare(double distance) {
    return 1.0 / (distance * distance + kFalloffBias);
}

// eq. 10 and 14: alpha' = saturate(alpha + sourceRadius / (3 distance)), (alpha / alpha')^2.
inline double sphereNormalization(double alpha, double sourceRadius, double distance) {
    const double widened = std::clamp(alpha + sourceRadius / (3.0 * distance), 0.0, 1.0);
    return (alpha / widened) * (alpha / widened);
}

// eq. 20 with the widening by half the tube's length over 3 distances (lights.glsl's analogy).
inline double tubeNormalization(double alpha, double sourceLength, double distance) {
    const double widened = std::clamp(alpha + sourceLength / (6.0 * distance), 0.0, 1.0);
    return alpha / widened;
}

// eq. 11: the point of the sphere (centre L, radius r) closest to the ray along R.
inline Vec3 sphereRepresentativePoint(const Vec3& L, const Vec3& R, double sourceRadius) {
    const Vec3 onRay = dot(L, R) * R;
    const Vec3 centerToRay = onRay - L;
    const double distanceToRay = length(centerToRay);
    const double reach = distanceToRay > 0.0 ? std::min(sourceRadius / distanceToRay, 1.0) : 0.0;
    return L + reach * centerToRay;
}

// eq. 19: t of the segment point L0 + t Ld whose direction is closest to R (found as the
// smallest distance between the segment's line and the line along R), clamped to [0, 1].
inline double tubeClosestParameter(const Vec3& L0, const Vec3& Ld, const Vec3& R) {
    const double RoLd = dot(R, Ld);
    const double t = (dot(R, L0) * RoLd - dot(L0, Ld)) / (dot(Ld, Ld) - RoLd * RoLd);
    return std::clamp(t, 0.0, 1.0);
}

// Adaptive Simpson quadrature of f over [a, b] to an absolute tolerance.
inline double integrate(const std::function<double(double)>& f, double a, double b,
                        double tolerance) {
    struct Simpson {
        const std::function<double(double)>& f;
        double step(double a, double b, double fa, double fm, double fb, double whole,
                    double tolerance, int depth) const {
            const double m = 0.5 * (a + b);
            const double lm = 0.5 * (a + m), rm = 0.5 * (m + b);
            const double flm = f(lm), frm = f(rm);
            const double left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
            const double right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
            if (depth <= 0 || std::fabs(left + right - whole) <= 15.0 * tolerance) {
                return left + right + (left + right - whole) / 15.0;
            }
            return step(a, m, fa, flm, fm, left, tolerance / 2, depth - 1) +
                   step(m, b, fm, frm, fb, right, tolerance / 2, depth - 1);
        }
    } simpson{f};
    const double fa = f(a), fb = f(b), fm = f(0.5 * (a + b));
    return simpson.step(a, b, fa, fm, fb, (b - a) / 6.0 * (fa + 4.0 * fm + fb), tolerance, 40);
}

// Irradiance (per unit radiance) from a sphere of angular radius sigma whose centre is
// theta from the normal: the integral over its cap of max(cos, 0) d(solid angle). Over the
// cap, direction = centre cos(psi) + sin(psi)(cos(phi) u + sin(phi) w), with u in the plane of
// the normal and the centre; then n.direction = A + B cos(phi), A = cos(theta) cos(psi),
// B = sin(theta) sin(psi) >= 0, and the clamped azimuthal integral is elementary:
// 2 pi A (circle above the horizon), 0 (below), or 2 (A phi0 + B sin phi0) with
// cos(phi0) = -A / B (cut by the horizon). psi is integrated numerically.
inline double sphereIrradianceByIntegration(double cosTheta, double sinSigma) {
    const double sinTheta = std::sqrt(std::max(1.0 - cosTheta * cosTheta, 0.0));
    const double sigma = std::asin(std::min(sinSigma, 1.0));
    auto ring = [&](double psi) {
        const double A = cosTheta * std::cos(psi);
        const double B = sinTheta * std::sin(psi);
        double azimuthal;
        if (A >= B) {
            azimuthal = 2.0 * std::numbers::pi * A;
        } else if (A <= -B) {
            azimuthal = 0.0;
        } else {
            const double phi0 = std::acos(-A / B);
            azimuthal = 2.0 * (A * phi0 + B * std::sin(phi0));
        }
        return azimuthal * std::sin(psi);
    };
    const double fullyAbove = std::numbers::pi * sinSigma * sinSigma;
    return integrate(ring, 0.0, sigma, 1e-12 * fullyAbove);
}

// Irradiance per unit intensity of a segment L0..L1 (vectors from the shaded point) whose
// intensity is spread evenly along it: the mean over the segment of max(n.L, 0) / |L| times
// the point-light falloff 1 / (|L|^2 + bias), as a point light at each of its points would
// give. Break points at the horizon crossing and the nearest point keep the quadrature exact.
inline double lineIrradianceByIntegration(const Vec3& N, const Vec3& L0, const Vec3& L1,
                                          double bias) {
    const Vec3 Ld = L1 - L0;
    auto integrand = [&](double t) {
        const Vec3 L = L0 + t * Ld;
        const double distance = length(L);
        if (distance == 0.0) return 0.0;
        return std::max(dot(N, L), 0.0) / distance / (distance * distance + bias);
    };
    std::array<double, 4> breaks = {0.0, 1.0, 0.0, 0.0};
    size_t count = 2;
    const double nL0 = dot(N, L0), nLd = dot(N, Ld);
    if (nLd != 0.0) {
        const double horizon = -nL0 / nLd;
        if (horizon > 0.0 && horizon < 1.0) breaks[count++] = horizon;
    }
    const double LdLd = dot(Ld, Ld);
    if (LdLd > 0.0) {
        const double nearest = -dot(L0, Ld) / LdLd;
        if (nearest > 0.0 && nearest < 1.0) breaks[count++] = nearest;
    }
    std::sort(breaks.begin(), breaks.begin() + count);
    // Tolerance relative to the largest cos-free falloff on the segment.
    double scale = 0.0;
    for (size_t i = 0; i < count; ++i) {
        const double d = length(L0 + breaks[i] * Ld);
        scale = std::max(scale, 1.0 / (d * d + bias));
    }
    double sum = 0.0;
    for (size_t i = 0; i + 1 < count; ++i) {
        if (breaks[i + 1] > breaks[i]) {
            sum += integrate(integrand, breaks[i], breaks[i + 1], 1e-12 * scale);
        }
    }
    return sum;
}

}  // namespace candela::stability::reference
