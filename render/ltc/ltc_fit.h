#pragma once
// Linearly transformed cosines (Heitz, Dupuy, Hill and Neubelt 2016) fitted to Candela's own
// specular lobe: GGX D (eq. 3) with the exact height-correlated Smith visibility (the
// energy-conserving BRDF's), times NoL, Fresnel = 1. Offline: `candela-ltc-fit` writes the
// table the area lights read; the tests check the fit against the lobe it fits. No Vulkan.
#include <array>
#include <cstdint>
#include <vector>

namespace candela::ltc {

struct Vec3 {
    double x = 0, y = 0, z = 0;
};

// Row-major 3x3: m[row][column], applied as m * v.
using Mat3 = std::array<std::array<double, 3>, 3>;

// The fitted parameters (a, c, b, tilt) of M = F R(tilt) [[a, 0, b], [0, c, 0], [0, 0, 1]], F the
// frame of the lobe's mean direction and R(tilt) a rotation about y; a chained fit starts the
// next cell from its neighbour's.
using Shape = std::array<double, 4>;

Vec3 operator*(const Mat3& m, const Vec3& v);
Mat3 inverse(const Mat3& m);
double determinant(const Mat3& m);

// The lobe being fitted, in the shading frame (N = +z, the view in the xz-plane, x >= 0):
//   value(L) = D(H) Vis(V, L) NoL, the specular BRDF times the cosine with F = 1.
// Its integral over the sphere is the lobe's directional albedo (the table's magnitude).
struct GgxLobe {
    double alpha;    // roughness^2, as alphaFromRoughness
    double cosView;  // NoV in (0, 1]

    Vec3 view() const;
    double value(const Vec3& l) const;
    // Visible-normal sampling (Heitz 2018): a direction and its solid-angle density.
    Vec3 sample(double u1, double u2, double* pdf) const;
    double pdf(const Vec3& l) const;
};

// A cosine lobe moved by M: density D(w) = Dcos(w') |det M^-1| / |M^-1 w|^3, w' = normalize(M^-1
// w).
struct TransformedCosine {
    Mat3 m;
    Mat3 mInverse;
    double jacobianScale;  // |det M^-1|

    static TransformedCosine from(const Mat3& m);
    double density(const Vec3& w) const;
    Vec3 sample(double u1, double u2) const;
};

// What the table stores per (roughness, view angle): M^-1 in the shading frame scaled so its
// middle element is 1 (integrals over a polygon do not depend on the scale), the lobe's
// magnitude n = integral of value(L), and its Fresnel part f = integral of value(L) (1 - VoH)^5,
// so that with Schlick's F the specular is F0 (n - f) + F90 f.
struct TableCell {
    double inverse00 = 1, inverse02 = 0, inverse20 = 0, inverse22 = 1;
    double magnitude = 0;
    double fresnel = 0;

    Mat3 inverseMatrix() const;
};

struct FitOptions {
    int samplesPerSide = 32;  // samplesPerSide^2 samples from each distribution per error estimate
    int maxIterations = 400;  // Nelder-Mead iterations per cell
};

// The fitted cosine lobe for one cell and the error of the fit.
struct CellFit {
    TableCell cell;
    double error = 0;  // l1Distance of the result
    Shape shape{};
};

// The fitted distance: the integral of |p - q| over the sphere, p the normalised lobe and q the
// transformed cosine, by multiple importance sampling of both (balance heuristic); 0 for a
// perfect fit, 2 for disjoint lobes. L1 rather than Heitz et al.'s |p - q|^3: it weighs the
// tails as much as the peak, and area lights integrate tails; on rectangles around the mirror
// direction it halved the mean specular error at roughness 0.4 (3.4 % to 1.9 %).
double l1Distance(const GgxLobe& lobe, double magnitude, const TransformedCosine& ltc,
                  int samplesPerSide);

// n and f of TableCell, by importance sampling the lobe.
void integrateMagnitude(const GgxLobe& lobe, int samplesPerSide, double* magnitude,
                        double* fresnel);

// Fits one cell. start: the shape of a neighbouring cell, or null for the isotropic guess.
CellFit fitCell(double roughness, double cosView, const FitOptions& options, const Shape* start);

// The table's axes: row r is roughness kMinRoughness + (1 - kMinRoughness) r / (size - 1)
// (the shader clamps roughness to kMinRoughness as brdf.glsl does), column c is
// cos(theta_v) = 1 - (c / (size - 1))^2 (finer towards grazing views), clamped to >= 1e-4.
double tableRoughness(int row, int size);
double tableCosView(int column, int size);

// The whole table, row-major (row = roughness). Each row is fitted from normal incidence (an
// isotropic first guess) towards grazing, each cell starting from its fitted neighbour; rows
// are independent, so threads split them.
std::vector<CellFit> fitTable(int size, const FitOptions& options, int threads);

inline constexpr double kMinRoughness = 0.02;  // brdf.glsl

}  // namespace candela::ltc
