// Wires (issue 19, seed 004 §6): Persson's clamp to a pixel's radius with the alpha scaled by
// real / clamped radius, and coverage from the distance to the centre line. An unlit emissive
// wire across the image keeps its energy (radiance summed down each column = width x
// radiance) from 20 px wide down to 0.1 px, where the naive one-pixel line is ten times too
// bright, and a 0.3 px wire moving by 1/8 pixel keeps its column sums (no flicker).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "wire_scene.h"

using namespace candela::render;
using namespace candela::render::test;
using namespace candela::render::test::wires;

namespace {

TEST(Wires, ColumnEnergyIsWidthTimesRadianceFrom20PixelsDownToATenth) {
    GpuContext context(requiredValidation());
    SceneResources resources(context);
    FrameSequence frames(context, kSize, kSize);
    RendererOptions naiveOptions;
    naiveOptions.wires = WireMode::Naive;
    FrameSequence naive(context, kSize, kSize, naiveOptions);
    WireScene scene;
    for (float width : {20.0f, 7.0f, 2.5f, 1.0f, 0.6f, 0.3f, 0.1f}) {
        const float depth = depthForWidth(width);
        ASSERT_NEAR(widthPixels(depth), width, 1e-3f * width);
        // Off the pixel grid: the centre line 0.3 px below a row boundary.
        const float pixel = 2.0f * depth * std::tan(kFov / 2.0f) / float(kSize);
        const FrameInputs inputs = scene.place(depth, 0.3f * pixel);
        RendererStats stats;
        const CapturedFrame frame = frames.render(inputs, resources, &stats);
        ASSERT_EQ(frame.nonFiniteHdrValues(), 0u);
        const double expected = double(width) * kEmission;
        EXPECT_LT(worstColumnError(frame, expected), 0.05) << width << " px wide";
        // The naive line is a pixel wide whatever the wire: 1 / width times the energy.
        const CapturedFrame line = naive.render(inputs, resources);
        const double naiveError = worstColumnError(line, expected);
        if (width <= 0.3f) {
            EXPECT_GT(naiveError, 1.0) << width << " px wide";
        }
    }
}

TEST(Wires, ASubpixelWireMovingByEighthPixelsKeepsItsColumnSums) {
    GpuContext context(requiredValidation());
    SceneResources resources(context);
    FrameSequence frames(context, kSize, kSize);
    WireScene scene;
    const float depth = depthForWidth(0.3f);
    const float pixel = 2.0f * depth * std::tan(kFov / 2.0f) / float(kSize);
    std::vector<std::vector<double>> sums;
    for (int step = 0; step < 16; ++step) {
        const CapturedFrame frame =
            frames.render(scene.place(depth, float(step) * pixel / 8.0f), resources);
        sums.push_back(columnSums(frame));
    }
    const double expected = 0.3 * kEmission;
    double worst = 0.0;
    for (uint32_t x = 0; x < kSize; ++x) {
        double lo = sums[0][x], hi = sums[0][x];
        for (const auto& frame : sums) {
            lo = std::min(lo, frame[x]);
            hi = std::max(hi, frame[x]);
        }
        worst = std::max(worst, (hi - lo) / expected);
        EXPECT_NEAR(sums[0][x], expected, 0.05 * expected) << "column " << x;
    }
    EXPECT_LT(worst, 0.05);
}

}  // namespace
