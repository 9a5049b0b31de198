// The post-process AA (render/src/passes/fxaa) on small synthetic images: an edge and its
// mirror image (left-right, up-down) or its transpose must be antialiased alike, pixel for
// pixel mirrored, since nothing in an edge's geometry prefers a side. A shader that picks the
// wrong side of an edge, walks the wrong way along it or samples half a texel off breaks this
// for one orientation only.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <vector>

#include "candela/render/gpu_context.h"
#include "candela/render/gpu_image.h"
#include "offscreen_frame.h"
#include "passes/fxaa/fxaa_pass.h"
#include "vk/image_transfer.h"

using namespace candela::render;

namespace {

constexpr uint32_t kSize = 40;

// RGBA8 texels, row-major, kSize x kSize.
using Image = std::vector<uint8_t>;

Image runFxaa(const Image& input) {
    GpuImage source(test::sharedContext(),
                    {VK_FORMAT_R8G8B8A8_UNORM, kSize, kSize, 1, false,
                     VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT});
    GpuImage target(test::sharedContext(),
                    {VK_FORMAT_R8G8B8A8_UNORM, kSize, kSize, 1, false,
                     VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT});
    writeImage(test::sharedContext(), source, 4, input.data());
    FxaaPass pass(test::sharedContext());
    test::sharedContext().submitAndWait([&](VkCommandBuffer cmd) {
        transitionImage(cmd, target, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                        VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE,
                        VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        pass.record(cmd, source, target);
        transitionImage(cmd, target, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL,
                        VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                        VK_ACCESS_2_TRANSFER_READ_BIT);
    });
    return readImage(test::sharedContext(), target, 4, VK_IMAGE_LAYOUT_GENERAL);
}

// Image whose pixel (x, y) is `source`'s pixel at map(x, y).
Image remap(const Image& source,
            const std::function<std::pair<uint32_t, uint32_t>(uint32_t, uint32_t)>& map) {
    Image out(source.size());
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            auto [sx, sy] = map(x, y);
            for (uint32_t c = 0; c < 4; ++c)
                out[(y * kSize + x) * 4 + c] = source[(sy * kSize + sx) * 4 + c];
        }
    }
    return out;
}

Image mirrorLeftRight(const Image& image) {
    return remap(image, [](uint32_t x, uint32_t y) { return std::pair{kSize - 1 - x, y}; });
}
Image mirrorUpDown(const Image& image) {
    return remap(image, [](uint32_t x, uint32_t y) { return std::pair{x, kSize - 1 - y}; });
}
Image transpose(const Image& image) {
    return remap(image, [](uint32_t x, uint32_t y) { return std::pair{y, x}; });
}

// A steep, nearly vertical staircase (one step every `run` rows) between a dark left and a
// bright right, like a distant pillar's silhouette, plus a thin 2-pixel bright bar (a pillar
// seen from far away) that leans the other way, and a one-pixel line of the same contrast on
// both sides: edges of both slopes and both sides.
Image pillarScene(uint32_t run) {
    Image image(kSize * kSize * 4);
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            const uint32_t edge = 8 + y / run;
            const uint32_t bar = 30 - y / (run + 3);
            uint8_t value = x >= edge ? 200 : 40;
            if (x >= bar && x < bar + 2) value = 230;
            if (x == bar + 2 && y % 2 == 0) value = 120;  // some texture on the bar's side
            if (x == 20 + y / (2 * run) && y < kSize / 2) value = 180;  // a one-pixel line
            uint8_t* p = &image[(y * kSize + x) * 4];
            p[0] = value;
            p[1] = static_cast<uint8_t>(value * 0.9);
            p[2] = static_cast<uint8_t>(value * 0.7);
            p[3] = 255;
        }
    }
    return image;
}

// Largest per-channel difference between two images, and the count of pixels FXAA changed.
int largestDifference(const Image& a, const Image& b, uint32_t* where) {
    int largest = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        const int d = std::abs(int(a[i]) - int(b[i]));
        if (d > largest) {
            largest = d;
            *where = static_cast<uint32_t>(i / 4);
        }
    }
    return largest;
}

size_t changedPixels(const Image& input, const Image& output) {
    size_t changed = 0;
    for (size_t i = 0; i < input.size(); i += 4) {
        changed +=
            input[i] != output[i] || input[i + 1] != output[i + 1] || input[i + 2] != output[i + 2];
    }
    return changed;
}

void expectSymmetric(const Image& input, Image (*mirror)(const Image&), const char* what) {
    const Image direct = runFxaa(input);
    const Image mirrored = runFxaa(mirror(input));
    ASSERT_GT(changedPixels(input, direct), 20u) << "FXAA left the " << what << " edges alone";
    uint32_t where = 0;
    // 1/255: the sRGB and ACES round trip of the blend may round a value either way.
    const int largest = largestDifference(direct, mirror(mirrored), &where);
    EXPECT_LE(largest, 1) << what << ": mirrored input gave an output that differs from the "
                          << "mirrored output by " << largest << "/255 at pixel (" << where % kSize
                          << ", " << where / kSize << ")";
}

TEST(Fxaa, MirroredLeftRightInputGivesMirroredOutput) {
    for (uint32_t run : {3u, 7u})
        expectSymmetric(pillarScene(run), &mirrorLeftRight, "left-right mirrored");
}

TEST(Fxaa, MirroredUpDownInputGivesMirroredOutput) {
    for (uint32_t run : {3u, 7u})
        expectSymmetric(pillarScene(run), &mirrorUpDown, "up-down mirrored");
}

TEST(Fxaa, TransposedInputGivesTransposedOutput) {
    for (uint32_t run : {3u, 7u})
        expectSymmetric(pillarScene(run), &transpose, "transposed");
}

}  // namespace
