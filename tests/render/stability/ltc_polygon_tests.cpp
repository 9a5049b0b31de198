// The shared LTC polygon integral (render/shaders/common/ltc.glsl) on the device: with
// M^-1 = identity it is the diffuse form factor of the polygon, checked against the closed form
// for rectangles parallel to the floor and against quadrature for rectangles that straddle the
// horizon or lie below it (issue 15: no light from below the horizon).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "error_stats.h"
#include "form_factors.h"
#include "light_accuracy.h"
#include "ltc_fit.h"

using namespace candela::stability;

namespace {

constexpr double kPi = std::numbers::pi;

struct Quad {
    std::array<std::array<double, 3>, 4> p;  // clockwise as seen from the lit side
};

// Midpoint quadrature of the point-to-area form factor over the part of the quad above the
// horizon (z > 0), one-sided: only where the point sees the quad's lit side.
double formFactorByQuadrature(const Quad& q, int n) {
    auto at = [&](double u, double v, int k) {
        const double bottom = q.p[0][k] + (q.p[1][k] - q.p[0][k]) * u;
        const double top = q.p[3][k] + (q.p[2][k] - q.p[3][k]) * u;
        return bottom + (top - bottom) * v;
    };
    std::array<double, 3> e1{}, e2{};
    for (int k = 0; k < 3; ++k)
        e1[k] = q.p[1][k] - q.p[0][k], e2[k] = q.p[3][k] - q.p[0][k];
    // Lit-side normal: clockwise from the lit side means e2 x e1 points towards it.
    const std::array<double, 3> normal{e2[1] * e1[2] - e2[2] * e1[1], e2[2] * e1[0] - e2[0] * e1[2],
                                       e2[0] * e1[1] - e2[1] * e1[0]};
    const double area =
        std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            const double u = (i + 0.5) / n, v = (j + 0.5) / n;
            const double x = at(u, v, 0), y = at(u, v, 1), z = at(u, v, 2);
            if (z <= 0.0) continue;
            const double r2 = x * x + y * y + z * z;
            // Towards the point from the surface: -p; its cosine with the lit normal.
            const double cosLight = -(x * normal[0] + y * normal[1] + z * normal[2]) / area;
            if (cosLight <= 0.0) continue;
            sum += (z / std::sqrt(r2)) * (cosLight / std::sqrt(r2)) / (kPi * r2);
        }
    }
    return sum * area / (double(n) * n);
}

LightSample quadSample(const Quad& q) {
    LightSample s;
    std::array<Float4*, 4> slots{&s.a, &s.b, &s.c, &s.d};
    for (int i = 0; i < 4; ++i) {
        for (int k = 0; k < 3; ++k)
            (*slots[i])[k] = float(q.p[i][k]);
    }
    s.a[3] = 1.0f, s.b[3] = 0.0f, s.c[3] = 0.0f, s.d[3] = 1.0f;  // M^-1 = identity
    return s;
}

// A ceiling rectangle [x0, x1] x [y0, y1] at height h, lit side down.
Quad ceiling(double x0, double x1, double y0, double y1, double h) {
    return Quad{{{{x0, y0, h}, {x1, y0, h}, {x1, y1, h}, {x0, y1, h}}}};
}

}  // namespace

// Within 1e-3 relative of the closed form wherever the rectangle covers at least 1e-3 of the
// hemisphere's cosine, over rectangles above, beside and far off the shading point, 1 cm to
// 100 m across. Far off and nearly edge-on, the four edge terms (each up to ~1) cancel to a
// sum under 1e-3, and fp32 leaves an absolute error of a few 1e-7 (3 % of 1.3e-5 measured):
// held to 2e-6 absolute there, a millionth of the light's full-hemisphere irradiance.
TEST(LtcPolygon, DiffuseRectangleMatchesTheClosedForm) {
    ComputeHarness harness;
    std::vector<LightSample> samples;
    std::vector<double> reference;
    for (double h : {0.05, 0.5, 2.0, 10.0}) {
        for (double size : {0.01, 0.3, 1.0, 4.0, 100.0}) {
            for (double offset : {0.0, 0.4, 1.5, 6.0}) {
                const double x0 = offset - size / 2, x1 = offset + size / 2;
                const double y0 = -0.3 * size, y1 = 0.7 * size;
                samples.push_back(quadSample(ceiling(x0, x1, y0, y1, h)));
                reference.push_back(parallelRectangleFormFactor(x0, x1, y0, y1, h));
            }
        }
    }
    const auto values = evaluateOnDevice(harness, LightFunction::LtcQuad, samples);
    WorstError relative;
    for (size_t i = 0; i < samples.size(); ++i) {
        if (reference[i] < 1e-3) continue;  // small and far off: absolute checked below
        relative.add(std::fabs(values[i][0] - reference[i]) / reference[i], [&] {
            return "value " + std::to_string(values[i][0]) + " reference " +
                   std::to_string(reference[i]);
        });
    }
    double worstAbsolute = 0.0;
    for (size_t i = 0; i < samples.size(); ++i)
        worstAbsolute = std::max(worstAbsolute, std::fabs(values[i][0] - reference[i]));
    relative.print("ltcPolygonIntegral, identity", "relative");
    EXPECT_LE(relative.error, 1e-3);
    EXPECT_LE(worstAbsolute, 2e-6);
    EXPECT_EQ(harness.validationMessages(), 0u);
}

// Walls that cross the horizon give the form factor of their upper part only; walls wholly
// below it and ceilings seen from their back side give exactly 0.
TEST(LtcPolygon, HorizonClippingLetsNoLightThroughFromBelow) {
    ComputeHarness harness;
    std::vector<Quad> quads;
    // A wall at x = d facing the point (lit side towards -x), from z = zLow to zHigh.
    for (double d : {0.2, 1.0, 3.0}) {
        for (auto [zLow, zHigh] : {std::pair{-1.0, 1.0}, {-0.2, 2.0}, {-3.0, 0.1}, {0.0, 1.0}}) {
            quads.push_back(
                Quad{{{{d, 1.0, zLow}, {d, 1.0, zHigh}, {d, -1.0, zHigh}, {d, -1.0, zLow}}}});
        }
    }
    const size_t straddling = quads.size();
    quads.push_back(Quad{{{{1, 1, -2}, {1, -1, -2}, {1, -1, -0.01}, {1, 1, -0.01}}}});  // below
    quads.push_back(Quad{{{{-1, -1, 1}, {-1, 1, 1}, {1, 1, 1}, {1, -1, 1}}}});          // back side
    std::vector<LightSample> samples;
    for (const Quad& q : quads)
        samples.push_back(quadSample(q));
    const auto values = evaluateOnDevice(harness, LightFunction::LtcQuad, samples);
    for (size_t i = 0; i < straddling; ++i) {
        const double reference = formFactorByQuadrature(quads[i], 1500);
        EXPECT_NEAR(values[i][0], reference, 2e-3 * reference + 1e-6) << "wall " << i;
    }
    EXPECT_EQ(values[straddling][0], 0.0f) << "wall below the horizon";
    EXPECT_EQ(values[straddling + 1][0], 0.0f) << "ceiling seen from its back";
    EXPECT_EQ(harness.validationMessages(), 0u);
}

namespace {

// Whether the ray from the origin along l crosses a ceiling quad (ceiling(): corners 0 and 2
// are opposite, all at one height).
bool rayHitsCeiling(const candela::ltc::Vec3& l, const Quad& q) {
    const auto& lo = q.p[0];
    const auto& hi = q.p[2];
    if (l.z <= 0.0) return false;
    const double t = lo[2] / l.z;
    const double x = l.x * t, y = l.y * t;
    return x >= lo[0] && x <= hi[0] && y >= lo[1] && y <= hi[1];
}

// The lobe's integral over a ceiling quad by visible-normal sampling, n x n stratified samples.
double lobeIntegralOverCeiling(const candela::ltc::GgxLobe& lobe, const Quad& q, int n) {
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            double pdf = 0.0;
            const candela::ltc::Vec3 l = lobe.sample((i + 0.5) / n, (j + 0.5) / n, &pdf);
            if (pdf > 0.0 && rayHitsCeiling(l, q)) sum += lobe.value(l) / pdf;
        }
    }
    return sum / (double(n) * n);
}

}  // namespace

// The specular of a rectangular light by LTC (a cell fitted by candela-ltc-fit's code, times
// its magnitude) against the lobe's own integral over the rectangle, for rectangles around the
// mirror direction and off it, where the rectangle catches at least 5 % of the lobe. Measured
// over 26 rectangles (3 roughnesses x 2 views): mean 1.0 %, worst 5.7 % (roughness 1 at a
// 60 degree view); issue 15's goal is 2 %, so the bound here guards the fit, not the goal.
TEST(LtcPolygon, SpecularOverARectangleMatchesTheLobesIntegral) {
    using namespace candela::ltc;
    ComputeHarness harness;
    FitOptions options;
    options.samplesPerSide = 24;
    struct Case {
        double roughness, cosView, reference;
        Quad quad;
    };
    std::vector<Case> cases;
    std::vector<LightSample> samples;
    for (double roughness : {0.15, 0.4, 1.0}) {
        Shape previous{};
        const Shape* start = nullptr;
        for (double cosView : {1.0, 0.5}) {
            const CellFit fit = fitCell(roughness, cosView, options, start);
            previous = fit.shape;
            start = &previous;
            const GgxLobe lobe{roughness * roughness, cosView};
            const double sinView = std::sqrt(1.0 - cosView * cosView);
            // The mirror direction is (-sinView, 0, cosView): ceilings at height 1 around where
            // it meets z = 1, of half-size 0.1 to 2 m, centred on it and 0.5 m off.
            const double mirrorX = -sinView / cosView;
            for (double halfSize : {0.1, 0.5, 2.0}) {
                for (double offset : {0.0, 0.5}) {
                    const double cx = mirrorX + offset;
                    Case c{roughness, cosView, 0.0,
                           ceiling(cx - halfSize, cx + halfSize, -halfSize, halfSize, 1.0)};
                    c.reference = lobeIntegralOverCeiling(lobe, c.quad, 400);
                    if (c.reference < 0.05 * fit.cell.magnitude) continue;
                    LightSample s = quadSample(c.quad);
                    s.a[3] = float(fit.cell.inverse00), s.b[3] = float(fit.cell.inverse02);
                    s.c[3] = float(fit.cell.inverse20), s.d[3] = float(fit.cell.inverse22);
                    samples.push_back(s);
                    c.reference /= fit.cell.magnitude;  // compared with the unit-mass LTC
                    cases.push_back(c);
                }
            }
        }
    }
    const auto values = evaluateOnDevice(harness, LightFunction::LtcQuad, samples);
    WorstError relative;
    double sumRelative = 0.0;
    for (size_t i = 0; i < cases.size(); ++i) {
        const double e = std::fabs(values[i][0] - cases[i].reference) / cases[i].reference;
        sumRelative += e;
        relative.add(e, [&] {
            char text[160];
            std::snprintf(text, sizeof text, "roughness %.2f cos %.2f: ltc %.4f lobe %.4f",
                          cases[i].roughness, cases[i].cosView, values[i][0], cases[i].reference);
            return std::string(text);
        });
    }
    relative.print("LTC specular over a rectangle", "relative");
    std::printf("  mean relative error %.4f over %zu rectangles\n",
                sumRelative / double(cases.size()), cases.size());
    EXPECT_GT(cases.size(), 20u);
    EXPECT_LE(relative.error, 0.08);
    EXPECT_EQ(harness.validationMessages(), 0u);
}
