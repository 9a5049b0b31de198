// The LTC tube (render/shaders/common/ltc_tube.glsl) on the device against the Lambertian
// capsule it stands for (issue 15: "tubes: a line plus end caps"): a thick tube (radius 0.3 m,
// length 1 m, 1 m away) with the checked-in table's M^-1 and magnitude at exact table cells,
// against the energy-conserving lobe integrated over the capsule's surface in double
// (the report's capsuleSpecularReference, report "area lights by LTC", capsule rows).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "../report/area_light_reference.h"
#include "light_accuracy.h"
#include "ltc_fit.h"
#include "ltc_ggx_table.inc"

using namespace candela::stability;
using candela::stability::reference::operator+;
using candela::stability::reference::operator*;

namespace {

struct TubeCase {
    double reference, magnitude, segmentMean;
    int row, column;
    double along;
};

}  // namespace

// R through the tube's centre and through its end cap (0.5 m along the axis), views 0 and about
// 30 degrees, roughness about 0.27, 0.52 and 1. The worst and mean relative error of the
// capsule LTC, and how far the bare segment's isotropic line would be off (the model the tube
// had before the capsule): the capsule must be at least 3x closer.
TEST(LtcTube, ThickTubeMatchesTheLambertianCapsule) {
    namespace report = candela::report;
    ComputeHarness harness;
    constexpr double kRadius = 0.3, kLength = 1.0;
    const report::Vec3 axis = {0.0, 1.0, 0.0};
    std::vector<LightSample> samples;
    std::vector<TubeCase> cases;
    for (int row : {16, 32, 63}) {
        for (int column : {0, 23}) {
            const auto& cell = kLtcTable[row * kLtcTableSize + column];
            const double roughness = candela::ltc::tableRoughness(row, kLtcTableSize);
            const double cosView = candela::ltc::tableCosView(column, kLtcTableSize);
            const double sinView = std::sqrt(1.0 - cosView * cosView);
            const double alpha = reference::alphaFromRoughness(roughness);
            // The table's frame: N = +z, V in the xz-plane with x >= 0; R = (-sin, 0, cos).
            const report::Vec3 V = {sinView, 0.0, cosView};
            for (double along : {0.0, 0.5}) {
                const report::Vec3 centre = {-sinView, along, cosView};
                const report::Vec3 p0 = centre + (-0.5 * kLength) * axis;
                const report::Vec3 p1 = centre + (0.5 * kLength) * axis;
                // Points a quarter of the lobe's width apart, at most 2 cm.
                const double spacing = std::min(alpha / 4.0, 0.02);
                const double reference = report::capsuleSpecularReference(
                    centre, axis, kLength, kRadius, V, alpha, spacing, true);
                LightSample s;
                s.a = {float(p0[0]), float(p0[1]), float(p0[2]), cell[0]};
                s.b = {float(p1[0]), float(p1[1]), float(p1[2]), cell[1]};
                s.c = {float(kRadius), 0.0f, 0.0f, cell[2]};
                s.d = {0.0f, 0.0f, 0.0f, cell[3]};
                samples.push_back(s);
                cases.push_back(
                    {reference, double(cell[4]),
                     report::tubeSpecularReference(centre, axis, kLength, V, alpha, 4096, true),
                     row, column, along});
            }
        }
    }
    const auto values = evaluateOnDevice(harness, LightFunction::LtcTube, samples);
    double worst = 0.0, worstGlossy = 0.0, sum = 0.0, segmentWorst = 0.0;
    for (size_t i = 0; i < cases.size(); ++i) {
        const TubeCase& c = cases[i];
        const double ltc = values[i][0] * c.magnitude;
        const double error = std::fabs(ltc - c.reference) / c.reference;
        const double segmentError = std::fabs(c.segmentMean - c.reference) / c.reference;
        std::printf(
            "row %2d column %2d along %.1f: capsule %.5g, LTC %.5g (%+.2f %%), bare "
            "segment lobe %+.1f %%\n",
            c.row, c.column, c.along, c.reference, ltc, 100.0 * (ltc / c.reference - 1.0),
            100.0 * (c.segmentMean / c.reference - 1.0));
        EXPECT_TRUE(std::isfinite(values[i][0]));
        worst = std::max(worst, error);
        if (c.row < 63) worstGlossy = std::max(worstGlossy, error);
        segmentWorst = std::max(segmentWorst, segmentError);
        sum += error;
    }
    const double mean = sum / double(cases.size());
    std::printf(
        "capsule LTC: worst %.2f %% (%.2f %% up to roughness 0.52), mean %.2f %%; bare "
        "segment (exact lobe): worst %.1f %%\n",
        100.0 * worst, 100.0 * worstGlossy, 100.0 * mean, 100.0 * segmentWorst);
    // Measured: 1.85 % up to roughness 0.52, 7.5 % at roughness 1 (R through the centre: the
    // capsule fills much of the broad lobe, where the fit's tails weigh), mean 2.4 %.
    EXPECT_LT(worstGlossy, 0.025);
    EXPECT_LT(worst, 0.10);
    EXPECT_LT(mean, 0.035);
    EXPECT_GT(segmentWorst, 3.0 * worst);
    EXPECT_EQ(harness.validationMessages(), 0u);
}
