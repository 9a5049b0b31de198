// Issue 44: a frame whose radiance holds NaN or Inf is counted (RendererStats::nonFinitePixels)
// and the frame after names the pass that wrote it (nonFiniteSource); a sound frame counts 0.
// The NaN comes from the test triangle's radiance, the one input that reaches the HDR target
// unchanged.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <string>

#include "frame_graph/frame_graph.h"
#include "offscreen_frame.h"
#include "passes/nonfinite/nonfinite_pass.h"
#include "passes/nonfinite/nonfinite_probes.h"

using namespace candela::render;

namespace {

constexpr uint32_t kWidth = 64;
constexpr uint32_t kHeight = 48;

FrameInputs triangle(float red) {
    FrameInputs inputs;
    inputs.scene.camera.ev100 = 1.0f;
    inputs.clearRadiance = {0.05f, 0.1f, 0.2f, 1.0f};
    inputs.testTriangleRadiance = {red, 0.5f, 0.125f, 1.0f};
    return inputs;
}

struct Frame {
    uint64_t nonFinitePixels = 0;
    std::string source;
    size_t capturedNonFinite = 0;
};

// Renders `inputs` twice with the check on; the second frame is a diagnosis frame when
// `diagnose`.
std::pair<Frame, Frame> twoFrames(const FrameInputs& inputs, bool diagnose) {
    GpuContext& context = test::sharedContext();
    RendererOptions options;
    options.checkNonFinite = true;
    Renderer renderer(context, kWidth, kHeight, options);
    FrameSubmitter submitter(context);
    FrameReadback readback(context, kWidth, kHeight);
    Frame frames[2];
    for (int i = 0; i < 2; ++i) {
        VkCommandBuffer cmd = renderer.recordFrame(submitter, inputs, nullptr);
        readback.recordCopy(cmd, renderer);
        submitter.submit();
        submitter.waitIdle();
        const RendererStats& stats = renderer.collectStats();
        frames[i] = {stats.nonFinitePixels, stats.nonFiniteSource,
                     readback.read().nonFiniteHdrValues()};
        if (i == 0 && diagnose) renderer.diagnoseNonFiniteNextFrame();
    }
    return {frames[0], frames[1]};
}

// The triangle's pixels: those the capture reads as non-finite (its red channel only).
TEST(NonFiniteGuard, ANaNRadianceIsCountedAndItsPassNamed) {
    const auto [first, second] = twoFrames(triangle(std::numeric_limits<float>::quiet_NaN()), true);
    ASSERT_GT(first.capturedNonFinite, 0u);
    EXPECT_EQ(first.nonFinitePixels, first.capturedNonFinite);  // one channel per pixel
    EXPECT_EQ(first.source, "");                                // not a diagnosis frame
    EXPECT_EQ(second.nonFinitePixels, first.nonFinitePixels);
    EXPECT_EQ(second.source.rfind("pass 'triangle' (image 'hdr', ", 0), 0u) << second.source;
    EXPECT_NE(second.source.find(std::to_string(first.nonFinitePixels) + " texels"),
              std::string::npos)
        << second.source;
}

TEST(NonFiniteGuard, AnInfiniteRadianceCountsToo) {
    const auto [first, second] = twoFrames(triangle(std::numeric_limits<float>::infinity()), false);
    EXPECT_GT(first.nonFinitePixels, 0u);
    EXPECT_EQ(first.nonFinitePixels, first.capturedNonFinite);
    EXPECT_EQ(second.source, "");  // nobody asked for a diagnosis
}

TEST(NonFiniteGuard, ASoundFrameCountsNothingAndItsProbesFindNothing) {
    const auto [first, second] = twoFrames(triangle(2.0f), true);
    EXPECT_EQ(first.nonFinitePixels, 0u);
    EXPECT_EQ(second.nonFinitePixels, 0u);
    EXPECT_EQ(second.source.rfind("no pass's float image held one", 0), 0u) << second.source;
}

// Compile-only: probes go after each pass that writes a float colour image, not after one
// writing an 8-bit or depth image; a probed transient is cleared first and gains SAMPLED.
TEST(NonFiniteProbes, FollowEveryFloatImageWriteAndClearTransientsFirst) {
    FrameGraph g;
    ResourceHandle radiance = g.createImage(
        "radiance", {VK_FORMAT_R16G16B16A16_SFLOAT, 8, 8, 1, false, VK_IMAGE_USAGE_STORAGE_BIT});
    ResourceHandle ldr = g.createImage(
        "ldr", {VK_FORMAT_R8G8B8A8_UNORM, 8, 8, 1, false, VK_IMAGE_USAGE_STORAGE_BIT});
    auto a = g.addPass("light", PassKind::Device, [](PassContext&) {});
    radiance = a.write(radiance, Use::StorageWrite);
    auto b = g.addPass("tonemap", PassKind::Device, [](PassContext&) {});
    b.read(radiance, Use::StorageRead);
    ldr = b.write(ldr, Use::StorageWrite);
    auto c = g.addPass("present", PassKind::Device, [](PassContext&) {});
    c.read(ldr, Use::StorageRead);
    c.sideEffect();

    GpuContext& context = test::sharedContext();
    NonFinitePass pass(context);
    const std::vector<NonFiniteProbe> probes = addNonFiniteProbes(g, pass, 1, 4);
    ASSERT_EQ(probes.size(), 1u);
    EXPECT_EQ(probes[0].passName, "light");
    EXPECT_EQ(probes[0].imageName, "radiance");
    EXPECT_EQ(probes[0].slot, 1u);
    EXPECT_TRUE(g.resources()[radiance.id].imageDesc.usage & VK_IMAGE_USAGE_SAMPLED_BIT);
    const CompiledFrameGraph compiled = compileFrameGraph(g);
    std::vector<std::string> order;
    for (uint32_t p : compiled.order)
        order.push_back(g.passes()[p].name);
    // The clear before the writer; the probe after it and before the image's next version.
    const auto at = [&](const std::string& name) {
        return std::find(order.begin(), order.end(), name) - order.begin();
    };
    EXPECT_LT(at("nonfinite_clear"), at("light"));
    EXPECT_LT(at("light"), at("nonfinite_probe"));
    EXPECT_EQ(order.size(), 5u);

    // The first probe with a count is the one whose writer ran first.
    std::vector<NonFiniteProbe> two = {{1, 2, "late", "x"}, {2, 0, "early", "y"}};
    EXPECT_EQ(firstNonFiniteProbe(two, {3, 5}, {0, 1, 2})->passName, "early");
    EXPECT_EQ(firstNonFiniteProbe(two, {3, 0}, {0, 1, 2})->passName, "late");
    EXPECT_EQ(firstNonFiniteProbe(two, {0, 0}, {0, 1, 2}), nullptr);
}

}  // namespace
