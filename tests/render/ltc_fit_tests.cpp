// The linearly transformed cosine fit (render/ltc/) against the lobe it fits: CPU only.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "ltc_fit.h"

using namespace candela::ltc;

namespace {

// The integral of a density over the sphere, by sampling the transformed cosine itself is
// circular; a latitude-longitude midpoint rule is independent of it.
template <class F>
double integrateSphere(F f, int n) {
    double sum = 0.0;
    const double pi = 3.14159265358979323846;
    for (int i = 0; i < n; ++i) {
        const double theta = pi * (i + 0.5) / n;
        for (int j = 0; j < 2 * n; ++j) {
            const double phi = pi * (j + 0.5) / n;
            const Vec3 w{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                         std::cos(theta)};
            sum += f(w) * std::sin(theta);
        }
    }
    return sum * (pi / n) * (pi / n);
}

}  // namespace

TEST(LtcFit, ATransformedCosineIntegratesToOne) {
    for (const Mat3& m :
         {Mat3{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, Mat3{{{0.5, 0, 0.3}, {0, 0.7, 0}, {-0.2, 0, 1}}},
          Mat3{{{2.0, 0, -0.5}, {0, 0.4, 0}, {0.1, 0, 1}}}}) {
        const TransformedCosine ltc = TransformedCosine::from(m);
        EXPECT_NEAR(integrateSphere([&](const Vec3& w) { return ltc.density(w); }, 400), 1.0, 2e-3);
    }
}

TEST(LtcFit, TheLobesSamplingDensityIntegratesToOneAndItsMagnitudeMatchesQuadrature) {
    for (double roughness : {0.3, 0.6, 1.0}) {
        for (double cosView : {1.0, 0.5, 0.1}) {
            const GgxLobe lobe{roughness * roughness, cosView};
            EXPECT_NEAR(integrateSphere([&](const Vec3& w) { return lobe.pdf(w); }, 600), 1.0, 5e-3)
                << roughness << " " << cosView;
            double magnitude = 0, fresnel = 0;
            integrateMagnitude(lobe, 128, &magnitude, &fresnel);
            const double quadrature =
                integrateSphere([&](const Vec3& w) { return lobe.value(w); }, 600);
            EXPECT_NEAR(magnitude, quadrature, 3e-3 * quadrature) << roughness << " " << cosView;
            EXPECT_GT(fresnel, 0.0);
            EXPECT_LT(fresnel, magnitude);
        }
    }
}

// A fit from the isotropic guess at normal incidence, then chained towards grazing views as the
// table does, stays close to the lobe: L1 distance (0 exact, 2 disjoint) per cell. Measured at
// cos 0.5 (the worst of these views): 0.037, 0.138 and 0.052; mid roughness at oblique views is
// where a cosine lobe fits GGX least well (the lobe is cut by the horizon).
TEST(LtcFit, FittedCellsAreCloseToTheLobe) {
    FitOptions options;
    options.samplesPerSide = 24;
    for (auto [roughness, bound] : {std::pair{0.2, 0.06}, {0.5, 0.25}, {1.0, 0.08}}) {
        const Shape* start = nullptr;
        CellFit previous;
        for (double cosView : {1.0, 0.9, 0.7, 0.5}) {
            const CellFit fit = fitCell(roughness, cosView, options, start);
            const GgxLobe lobe{roughness * roughness, cosView};
            const double d =
                l1Distance(lobe, fit.cell.magnitude,
                           TransformedCosine::from(inverse(fit.cell.inverseMatrix())), 64);
            EXPECT_LT(d, bound) << "roughness " << roughness << " cos " << cosView;
            previous = fit;
            start = &previous.shape;
        }
    }
}

namespace {
#include "ltc_ggx_table.inc"
}  // namespace

// The checked-in table is what candela-ltc-fit makes of today's lobe: at cells across it, the
// magnitude and Fresnel part match a fresh integration, and the stored M^-1 is as close to the
// lobe as a fresh fit of that cell (a stale table, fitted to another BRDF, fails both).
TEST(LtcFit, TheCheckedInTableFitsTodaysLobe) {
    ASSERT_EQ(kLtcTableSize, 64);
    FitOptions options;
    options.samplesPerSide = 24;
    for (int row : {5, 20, 40, 63}) {
        for (int column : {0, 20, 45}) {
            const float* stored = kLtcTable[row * kLtcTableSize + column];
            const double roughness = tableRoughness(row, kLtcTableSize);
            const GgxLobe lobe{roughness * roughness, tableCosView(column, kLtcTableSize)};
            double magnitude = 0, fresnel = 0;
            integrateMagnitude(lobe, 128, &magnitude, &fresnel);  // the tool's 4 x 32 per side
            EXPECT_NEAR(stored[4], magnitude, 1e-6) << row << " " << column;
            EXPECT_NEAR(stored[5], fresnel, 1e-6) << row << " " << column;
            TableCell cell;
            cell.inverse00 = stored[0], cell.inverse02 = stored[1];
            cell.inverse20 = stored[2], cell.inverse22 = stored[3];
            const double storedDistance = l1Distance(
                lobe, magnitude, TransformedCosine::from(inverse(cell.inverseMatrix())), 48);
            const CellFit fresh =
                fitCell(roughness, tableCosView(column, kLtcTableSize), options, nullptr);
            const double freshDistance = l1Distance(
                lobe, magnitude, TransformedCosine::from(inverse(fresh.cell.inverseMatrix())), 48);
            EXPECT_LE(storedDistance, freshDistance + 0.02) << row << " " << column;
        }
    }
}
