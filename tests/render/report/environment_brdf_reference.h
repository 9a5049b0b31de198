#pragma once
// Eq. 8 in double precision: (scale, bias) of F0 in the integral of the specular BRDF (eq. 3
// D, eq. 4 Vis, pow5 Fresnel) over a white environment, by visible-normal sampling (Heitz
// 2018) on a stratified n x n grid of midpoints. Written for the report from the formulas,
// not from ibl.glsl's code.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace candela::report {

inline std::pair<double, double> environmentBrdfReference(double roughness, double NoV, int n) {
    constexpr double kPi = std::numbers::pi;
    NoV = std::max(NoV, 1e-4);
    const double alpha = roughness * roughness;
    const double a2 = alpha * alpha;
    const double k = alpha / 2.0;
    const double vx = std::sqrt(1.0 - NoV * NoV), vz = NoV;
    // The view stretched into the hemisphere configuration; V has no y component.
    double hx = alpha * vx, hz = vz;
    const double hl = std::sqrt(hx * hx + hz * hz);
    hx /= hl;
    hz /= hl;
    // T1 = (0, 1, 0) when hx > 0 (the view leans), (1, 0, 0) at normal incidence; T2 = Vh x T1.
    const bool leaning = hx > 0.0;
    const double g1Schlick = NoV / (NoV * (1.0 - k) + k);
    const double g1Exact = 2.0 * NoV / (NoV + std::sqrt(a2 + (1.0 - a2) * NoV * NoV));
    double a = 0.0, b = 0.0;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            const double r = std::sqrt((i + 0.5) / n);
            const double phi = 2.0 * kPi * (j + 0.5) / n;
            const double t1 = r * std::cos(phi);
            const double s = 0.5 * (1.0 + hz);
            const double t2 =
                (1.0 - s) * std::sqrt(std::max(1.0 - t1 * t1, 0.0)) + s * r * std::sin(phi);
            const double t3 = std::sqrt(std::max(1.0 - t1 * t1 - t2 * t2, 0.0));
            // Nh = t1 T1 + t2 T2 + t3 Vh.
            double nx, ny, nz;
            if (leaning) {
                // T1 = (0, 1, 0), T2 = Vh x T1 = (-hz, 0, hx).
                nx = -t2 * hz + t3 * hx;
                ny = t1;
                nz = t2 * hx + t3 * hz;
            } else {
                // T1 = (1, 0, 0), T2 = (0, 1, 0), Vh = (0, 0, 1).
                nx = t1;
                ny = t2;
                nz = t3;
            }
            double Hx = alpha * nx, Hy = alpha * ny, Hz = std::max(nz, 1e-12);
            const double hn = std::sqrt(Hx * Hx + Hy * Hy + Hz * Hz);
            Hx /= hn;
            Hy /= hn;
            Hz /= hn;
            const double VoH = vx * Hx + vz * Hz;
            const double NoL = 2.0 * VoH * Hz - vz;
            if (NoL <= 0.0 || VoH <= 0.0) continue;
            const double weight = g1Schlick * (NoL / (NoL * (1.0 - k) + k)) / g1Exact;
            const double fc = std::pow(1.0 - VoH, 5.0);
            a += (1.0 - fc) * weight;
            b += fc * weight;
        }
    }
    return {a / (double(n) * n), b / (double(n) * n)};
}

}  // namespace candela::report
