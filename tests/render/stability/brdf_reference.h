#pragma once
// Double-precision reference of the BRDF terms, written from the formulas of Karis 2013, "Real
// Shading in Unreal Engine 4", "Shading Model" (eq. 1-5) and Karis 2014, "Physically Based Shading
// on Mobile" (EnvBRDFApprox), in forms chosen to be independent of the GLSL's operation order (tan
// form of GGX, Smith's G1 quotients, Heitz's Lambda).
#include <algorithm>
#include <cmath>
#include <numbers>

namespace candela::stability::reference {

constexpr double kPi = std::numbers::pi;
constexpr double kMinRoughness = 0.02;  // the clamp documented in brdf.glsl

inline double saturate(double x) {
    return std::clamp(x, 0.0, 1.0);
}

inline double alphaFromRoughness(double roughness) {
    const double r = std::clamp(roughness, kMinRoughness, 1.0);
    return r * r;
}

// eq. 1
inline double lambert(double diffuseColor) {
    return diffuseColor / kPi;
}

// eq. 3 rewritten with tan^2(theta_h) = (1 - NoH^2) / NoH^2, the (1 - NoH)(1 + NoH) product
// exact in double: D = alpha^2 / (pi cos^4 (alpha^2 + tan^2)^2).
inline double ggxDistribution(double alpha, double NoH) {
    const double a2 = alpha * alpha;
    const double sinSq = (1.0 - NoH) * (1.0 + NoH);
    const double cosSq = NoH * NoH;
    const double denominator = a2 * cosSq + sinSq;  // cos^2 (a2 + tan^2)
    return a2 / (kPi * denominator * denominator);
}

// eq. 4: Schlick's G1 with k = alpha / 2, G = G1(l) G1(v); divided by 4 NoL NoV (eq. 2).
// Requires NoV, NoL > 0.
inline double smithSchlickVisibility(double alpha, double NoV, double NoL) {
    const double k = alpha / 2.0;
    auto g1 = [k](double c) { return c / (c * (1.0 - k) + k); };
    return g1(NoV) * g1(NoL) / (4.0 * NoL * NoV);
}

// Height-correlated Smith (Heitz 2014): G2 = 1 / (1 + Lambda(v) + Lambda(l)),
// Lambda = (sqrt(1 + alpha^2 tan^2 theta) - 1) / 2. Requires NoV, NoL > 0.
inline double smithGgxCorrelatedVisibility(double alpha, double NoV, double NoL) {
    auto lambda = [alpha](double c) {
        const double tanSq = (1.0 - c * c) / (c * c);
        return (std::sqrt(1.0 + alpha * alpha * tanSq) - 1.0) / 2.0;
    };
    const double g2 = 1.0 / (1.0 + lambda(NoV) + lambda(NoL));
    return g2 / (4.0 * NoL * NoV);
}

// eq. 5, with the SPEC's rule that F0 under 2% is pre-baked shadowing: the grazing term is
// scaled by saturate(50 F0.g). f0Green is the green channel of the specular colour.
inline double fresnelSchlickSg(double f0, double f0Green, double VoH) {
    const double grazing = std::exp2((-5.55473 * VoH - 6.98316) * VoH);
    return f0 * (1.0 - grazing) + saturate(50.0 * f0Green) * grazing;
}

// Schlick's original (1 - VoH)^5, which eq. 5 approximates; same shadowing rule.
inline double fresnelSchlickPow5(double f0, double f0Green, double VoH) {
    const double grazing = std::pow(1.0 - VoH, 5.0);
    return f0 * (1.0 - grazing) + saturate(50.0 * f0Green) * grazing;
}

// Karis 2014's fit as scale and bias of F0: F0 * A + B.
struct ScaleBias {
    double scale;
    double bias;
};

inline ScaleBias envBrdfApproxScaleBias(double roughness, double NoV) {
    // Coefficients of Karis 2014, written per output: r = roughness * c0 + c1.
    const double rx = 1.0 - roughness;
    const double ry = 0.0425 - 0.0275 * roughness;
    const double rz = 1.04 - 0.572 * roughness;
    const double rw = -0.04 + 0.022 * roughness;
    const double a004 = std::min(rx * rx, std::exp2(-9.28 * NoV)) * rx + ry;
    return {rz - 1.04 * a004, rw + 1.04 * a004};
}

inline double envBrdfApprox(double f0, double roughness, double NoV) {
    const ScaleBias ab = envBrdfApproxScaleBias(roughness, NoV);
    return f0 * ab.scale + ab.bias;
}

// Karis 2014's non-metal variant returns a004 itself.
inline double envBrdfApproxNonmetal(double roughness, double NoV) {
    const double rx = 1.0 - roughness;
    return std::min(rx * rx, std::exp2(-9.28 * NoV)) * rx + (0.0425 - 0.0275 * roughness);
}

}  // namespace candela::stability::reference
