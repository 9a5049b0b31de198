// Wires (issue 19, Persson 2014, GPU Pro 5, "Wire Antialiasing"): Persson's clamp to a pixel's
// radius with the alpha scaled by real / clamped radius, and coverage from the distance to the
// centre line. An unlit emissive wire across the image keeps its energy (radiance summed down each
// column = width x radiance) from 20 px wide down to 0.1 px (where the naive one-pixel line is ten
// times too bright: candela-report's wire rows), and a 0.3 px wire moving by 1/8 pixel keeps its
// column sums (no flicker).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "wire_scene.h"

using namespace candela::render;
using namespace candela::render::test;
using namespace candela::render::test::wires;

namespace {

// One device, scene store and renderer for both cases: the renderer's set-up (its pipelines
// on lavapipe) costs more than the frames.
class Wires : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        context_ = new GpuContext(requiredValidation());
        resources_ = new SceneResources(*context_);
        // Froxels: only frames with fog (the fog case) draw the medium.
        RendererOptions options;
        options.volumetrics = VolumetricsMode::Froxels;
        frames_ = new FrameSequence(*context_, kSize, kSize, options);
    }
    static void TearDownTestSuite() {
        delete frames_;
        delete resources_;
        delete context_;
    }
    CapturedFrame render(const FrameInputs& inputs) { return frames_->render(inputs, *resources_); }

    static GpuContext* context_;
    static SceneResources* resources_;
    static FrameSequence* frames_;
};
GpuContext* Wires::context_ = nullptr;
SceneResources* Wires::resources_ = nullptr;
FrameSequence* Wires::frames_ = nullptr;

TEST_F(Wires, ColumnEnergyIsWidthTimesRadianceFrom20PixelsDownToATenth) {
    WireScene scene;
    for (float width : {20.0f, 7.0f, 2.5f, 1.0f, 0.6f, 0.3f, 0.1f}) {
        const float depth = depthForWidth(width);
        ASSERT_NEAR(widthPixels(depth), width, 1e-3f * width);
        // Off the pixel grid: the centre line 0.3 px below a row boundary.
        const float pixel = 2.0f * depth * std::tan(kFov / 2.0f) / float(kSize);
        const CapturedFrame frame = render(scene.place(depth, 0.3f * pixel));
        ASSERT_EQ(frame.nonFiniteHdrValues(), 0u);
        const double error = worstColumnError(frame, double(width) * kEmission);
        std::printf("%5.2f px wide: worst column energy error %.2e\n", width, error);
        EXPECT_LT(error, 0.05) << width << " px wide";
        // Slanted 20 degrees: a column crosses it over width / cos(20 degrees).
        const float slope = std::tan(glm::radians(20.0f));
        const double slanted =
            worstColumnError(render(scene.place(depth, 0.3f * pixel, slope)),
                             double(width) * kEmission * std::sqrt(1.0 + slope * slope));
        std::printf("%5.2f px wide, slanted 20 degrees: worst column energy error %.2e\n", width,
                    slanted);
        EXPECT_LT(slanted, 0.05) << width << " px wide, slanted";
    }
}

TEST_F(Wires, ASubpixelWireMovingByEighthPixelsKeepsItsColumnSums) {
    WireScene scene;
    const float depth = depthForWidth(0.3f);
    const float pixel = 2.0f * depth * std::tan(kFov / 2.0f) / float(kSize);
    std::vector<std::vector<double>> sums;
    for (int step = 0; step < 16; ++step) {
        sums.push_back(columnSums(render(scene.place(depth, float(step) * pixel / 8.0f))));
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
    std::printf("0.3 px wire, 16 steps of 1/8 px: column sums change by %.2e\n", worst);
    EXPECT_LT(worst, 0.05);
}

// A wire running away from a pitched camera in its vertical plane: on screen a vertical line
// whose ends differ in depth, the case lavapipe's clipper once turned into NaN coverage. Its
// row sums (the energy across it) match the same wire a millimetre to the side.
TEST_F(Wires, AWireInAPitchedCamerasVerticalPlaneKeepsItsEnergy) {
    WireScene scene;
    const glm::mat4 pitched = glm::rotate(glm::mat4(1.0f), glm::radians(-10.0f), {1, 0, 0});
    auto rowSums = [&](float x) {
        scene.camera.view = pitched;
        // Under a pixel wide everywhere (so both ends of a quad reach out equally far on
        // screen, the case that gave 0 / 0), in 2 m segments as a cable between poles is.
        scene.wire.radius = 0.002f;
        scene.wire.positions.clear();
        scene.wire.segments.clear();
        for (uint32_t i = 0; i <= 60; ++i) {
            scene.wire.positions.push_back({x, 2.0f, -1.0f - 2.0f * float(i)});
            if (i > 0) scene.wire.segments.insert(scene.wire.segments.end(), {i - 1, i});
        }
        scene.draws = {{&scene.wire, &scene.material, glm::mat4(1.0f)}};
        FrameInputs inputs;
        inputs.scene.camera = scene.camera;
        inputs.scene.wires = scene.draws;
        const CapturedFrame frame = render(inputs);
        EXPECT_EQ(frame.nonFiniteHdrValues(), 0u) << "x = " << x;
        std::vector<double> sums(frame.height, 0.0);
        for (uint32_t y = 0; y < frame.height; ++y) {
            for (uint32_t column = 0; column < frame.width; ++column)
                sums[y] += hdrPixel(frame, column, y)[0];
        }
        return sums;
    };
    const std::vector<double> inPlane = rowSums(0.0f);
    const std::vector<double> aside = rowSums(1e-3f);
    double worst = 0.0;
    uint32_t lit = 0;
    for (uint32_t y = 0; y < kSize; ++y) {
        if (aside[y] < 0.001 * kEmission) continue;  // rows the wire does not cross
        ++lit;
        worst = std::max(worst, std::abs(inPlane[y] / aside[y] - 1.0));
    }
    std::printf("wire in the vertical plane: %u rows, worst row energy error %.2e\n", lit, worst);
    EXPECT_GT(lit, kSize / 4);
    EXPECT_LT(worst, 0.05);
}

// A wire inside uniform fog (froxels, no lights, so no in-scattering): its column energy is
// attenuated by the transmittance to it, as a blended surface's is.
TEST_F(Wires, InFogAreAttenuatedByTheTransmittanceToThem) {
    WireScene scene;
    const float width = 2.5f;
    const float depth = depthForWidth(width);
    FrameInputs inputs = scene.place(depth, 0.0f);
    candela::content::Fog fog;
    fog.scattering = 0.08f;
    fog.absorption = 0.04f;
    inputs.scene.fog = fog;
    const CapturedFrame frame = render(inputs);
    ASSERT_EQ(frame.nonFiniteHdrValues(), 0u);
    // Each column sees the wire along its own ray, longer than the view depth off the axis.
    const std::vector<double> sums = columnSums(frame);
    double error = 0.0;
    for (uint32_t x = 0; x < kSize; ++x) {
        const double slope = ((x + 0.5) / kSize * 2.0 - 1.0) * std::tan(kFov / 2.0);
        const double distance = double(depth) * std::sqrt(1.0 + slope * slope);
        const double expected = double(width) * kEmission * std::exp(-0.12 * distance);
        error = std::max(error, std::abs(sums[x] / expected - 1.0));
    }
    std::printf("wire %.1f m into fog (T = %.3f on the axis): worst column energy error %.2e\n",
                depth, std::exp(-0.12 * double(depth)), error);
    // Froxels interpolate the transmittance between exponential slice boundaries.
    EXPECT_LT(error, 0.02);
}

}  // namespace
