#pragma once
// Closed-form diffuse form factors of ceiling lights over a floor point, the references the
// LTC and area-light irradiance tests compare against (irradiance per unit luminance is pi x
// the form factor).
#include <cmath>
#include <numbers>

namespace candela::stability {

// From a point to the rectangle [0, a] x [0, b] at height h above it, the point under the
// corner (the classic closed form; a quarter of the infinite plane gives 1/4).
inline double cornerFormFactor(double a, double b, double h) {
    const double A = a / h, B = b / h;
    const double sa = std::sqrt(1.0 + A * A), sb = std::sqrt(1.0 + B * B);
    return (A / sa * std::atan(B / sa) + B / sb * std::atan(A / sb)) / (2.0 * std::numbers::pi);
}

// The rectangle [x0, x1] x [y0, y1] at height h over the origin, by inclusion-exclusion of
// corner rectangles.
inline double parallelRectangleFormFactor(double x0, double x1, double y0, double y1, double h) {
    auto signedCorner = [h](double x, double y) {
        const double s = (x < 0 ? -1.0 : 1.0) * (y < 0 ? -1.0 : 1.0);
        return s * cornerFormFactor(std::fabs(x), std::fabs(y), h);
    };
    return signedCorner(x1, y1) - signedCorner(x0, y1) - signedCorner(x1, y0) +
           signedCorner(x0, y0);
}

// A parallel disk of radius r at height h whose centre is offset by a horizontally
// (r^2 / (h^2 + r^2) straight under it).
inline double parallelDiskFormFactor(double r, double h, double a) {
    const double sum = h * h + a * a + r * r;
    return 0.5 * (1.0 - (h * h + a * a - r * r) / std::sqrt(sum * sum - 4.0 * a * a * r * r));
}

}  // namespace candela::stability
