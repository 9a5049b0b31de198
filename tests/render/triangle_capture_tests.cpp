// Clear + one triangle, captured to EXR and PNG, checked pixel by pixel against an independent
// CPU model of coverage, exposure, the ACES fit and sRGB encoding.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "candela/content/exr_image.h"
#include "offscreen_frame.h"

extern "C" unsigned char* stbi_load_from_memory(const unsigned char* buffer, int len, int* x,
                                                int* y, int* comp, int req_comp);
extern "C" void stbi_image_free(void* data);

using namespace candela::render;

namespace {

constexpr uint32_t kWidth = 96;
constexpr uint32_t kHeight = 64;
constexpr std::array<std::array<float, 2>, 3> kCorners = {
    {{0.0f, -0.6f}, {0.6f, 0.6f}, {-0.6f, 0.6f}}};

FrameInputs testScene() {
    FrameInputs inputs;
    inputs.scene.camera.ev100 = 1.0f;
    inputs.clearRadiance = {0.05f, 0.1f, 0.2f, 1.0f};
    inputs.testTriangleRadiance = {2.0f, 0.5f, 0.125f, 1.0f};
    return inputs;
}

// Signed edge value of the pixel centre against each edge; all positive = inside.
enum class Coverage { Inside, Outside, OnEdge };
Coverage coverage(uint32_t x, uint32_t y) {
    const double px = (x + 0.5) / kWidth * 2.0 - 1.0;
    const double py = (y + 0.5) / kHeight * 2.0 - 1.0;
    int positive = 0;
    for (int i = 0; i < 3; ++i) {
        const auto& a = kCorners[i];
        const auto& b = kCorners[(i + 1) % 3];
        double edge = (b[0] - a[0]) * (py - a[1]) - (b[1] - a[1]) * (px - a[0]);
        double length = std::hypot(b[0] - a[0], b[1] - a[1]);
        double pixelsFromEdge = std::abs(edge) / length * std::min(kWidth, kHeight) / 2.0;
        if (pixelsFromEdge < 0.01) return Coverage::OnEdge;
        positive += edge > 0 ? 1 : 0;
    }
    return positive == 3 || positive == 0 ? Coverage::Inside : Coverage::Outside;
}

double acesFit(double x) {
    double v = (x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14);
    return std::clamp(v, 0.0, 1.0);
}

double srgbEncode(double linear) {
    return linear <= 0.0031308 ? linear * 12.92 : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

uint8_t expectedLdr(float radiance, float ev100) {
    double exposure = 1.0 / (1.2 * std::exp2(double(ev100)));
    return uint8_t(std::lround(255.0 * srgbEncode(acesFit(radiance * exposure))));
}

std::vector<unsigned char> readFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST(TriangleCapture, HdrAndLdrMatchPixelByPixel) {
    GpuContext context(test::requiredValidation());
    const FrameInputs inputs = testScene();
    CapturedFrame frame = test::renderOffscreen(context, inputs, kWidth, kHeight);
    ASSERT_EQ(frame.hdrRgb.size(), size_t(kWidth) * kHeight * 3);
    EXPECT_EQ(frame.nonFiniteHdrValues(), 0u);

    size_t inside = 0, outside = 0, mismatches = 0;
    for (uint32_t y = 0; y < kHeight; ++y) {
        for (uint32_t x = 0; x < kWidth; ++x) {
            Coverage c = coverage(x, y);
            if (c == Coverage::OnEdge) continue;
            const auto& expected =
                c == Coverage::Inside ? *inputs.testTriangleRadiance : inputs.clearRadiance;
            (c == Coverage::Inside ? inside : outside)++;
            const size_t i = size_t(y) * kWidth + x;
            for (int ch = 0; ch < 3; ++ch) {
                bool hdrOk = frame.hdrRgb[i * 3 + ch] == expected[ch];
                int ldrDelta = int(frame.ldrRgba[i * 4 + ch]) -
                               int(expectedLdr(expected[ch], inputs.scene.camera.ev100));
                if (!hdrOk || std::abs(ldrDelta) > 1) ++mismatches;
            }
            if (frame.ldrRgba[i * 4 + 3] != 255) ++mismatches;
        }
    }
    EXPECT_GT(inside, 1000u);
    EXPECT_GT(outside, 1000u);
    EXPECT_EQ(mismatches, 0u);
    EXPECT_EQ(context.validationMessages(), 0u);
}

TEST(TriangleCapture, ExrAndPngFilesHoldTheCapture) {
    GpuContext context(test::requiredValidation());
    CapturedFrame frame = test::renderOffscreen(context, testScene(), kWidth, kHeight);
    const auto dir = std::filesystem::path(testing::TempDir()) / "candela_capture";
    std::filesystem::create_directories(dir);

    ASSERT_EQ(writeCapture(dir / "frame.exr", frame), "");
    candela::content::Diagnostics diagnostics;
    auto exr = candela::content::readExrImage(dir / "frame.exr", diagnostics);
    ASSERT_TRUE(exr.has_value());
    ASSERT_EQ(exr->image.width, kWidth);
    ASSERT_EQ(exr->image.height, kHeight);
    for (uint32_t y = 0; y < kHeight; ++y) {
        for (uint32_t x = 0; x < kWidth; ++x) {
            const float* texel = exr->image.texel(x, y);
            const float* captured = &frame.hdrRgb[(size_t(y) * kWidth + x) * 3];
            ASSERT_EQ(std::memcmp(texel, captured, 3 * sizeof(float)), 0) << x << "," << y;
        }
    }

    ASSERT_EQ(writeCapture(dir / "frame.png", frame), "");
    std::vector<unsigned char> png = readFile(dir / "frame.png");
    int w = 0, h = 0, comp = 0;
    unsigned char* pixels = stbi_load_from_memory(png.data(), int(png.size()), &w, &h, &comp, 4);
    ASSERT_NE(pixels, nullptr);
    EXPECT_EQ(w, int(kWidth));
    EXPECT_EQ(h, int(kHeight));
    EXPECT_EQ(std::memcmp(pixels, frame.ldrRgba.data(), frame.ldrRgba.size()), 0);
    stbi_image_free(pixels);
}

TEST(TriangleCapture, SameSceneSameFrameSamePixels) {
    GpuContext context(test::requiredValidation());
    CapturedFrame a = test::renderOffscreen(context, testScene(), kWidth, kHeight, 3);
    CapturedFrame b = test::renderOffscreen(context, testScene(), kWidth, kHeight, 3);
    EXPECT_EQ(a.hdrRgb, b.hdrRgb);
    EXPECT_EQ(a.ldrRgba, b.ldrRgba);
}

TEST(TriangleCapture, WriteCaptureRejectsBadPaths) {
    CapturedFrame frame;
    frame.width = 1;
    frame.height = 1;
    frame.hdrRgb = {0.0f, 0.0f, 0.0f};
    frame.ldrRgba = {0, 0, 0, 255};
    EXPECT_NE(writeCapture("/nonexistent-dir/x.png", frame), "");
    EXPECT_NE(writeCapture("/nonexistent-dir/x.exr", frame), "");
    EXPECT_NE(writeCapture("frame.bmp", frame).find("unknown capture format"), std::string::npos);
}
