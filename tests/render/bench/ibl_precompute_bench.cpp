// Precompute cost of image-based lighting on this device: a 2k lat-long sky (2048x1024, made
// by upsampling a shared 1k sky, since the shared assets hold none that large), loaded with an
// empty cache and again from the cache, plus the environment BRDF LUT. Medians of N runs.
//
//   build/bin/candela-bench-ibl [runs]
#include <algorithm>
#include <bit>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <vector>

#include "candela/content/exr_image.h"
#include "candela/render/environment.h"
#include "candela/render/gpu_context.h"
#include "ibl/environment_brdf_lut.h"
#include "median.h"

using namespace candela;

namespace {

// Bilinear 2x upsampling of `source` into a width x height RGB float image.
std::vector<float> upsample(const content::FloatImage& source, uint32_t width, uint32_t height) {
    std::vector<float> rgb(size_t(width) * height * 3);
    for (uint32_t y = 0; y < height; ++y) {
        float sy = std::clamp((float(y) + 0.5f) * float(source.height) / float(height) - 0.5f, 0.0f,
                              float(source.height - 1));
        uint32_t y0 = uint32_t(sy), y1 = std::min(y0 + 1, source.height - 1);
        float fy = sy - float(y0);
        for (uint32_t x = 0; x < width; ++x) {
            float sx = std::clamp((float(x) + 0.5f) * float(source.width) / float(width) - 0.5f,
                                  0.0f, float(source.width - 1));
            uint32_t x0 = uint32_t(sx), x1 = std::min(x0 + 1, source.width - 1);
            float fx = sx - float(x0);
            for (int c = 0; c < 3; ++c) {
                float top = source.texel(x0, y0)[c] * (1 - fx) + source.texel(x1, y0)[c] * fx;
                float bottom = source.texel(x0, y1)[c] * (1 - fx) + source.texel(x1, y1)[c] * fx;
                rgb[(size_t(y) * width + x) * 3 + c] = top * (1 - fy) + bottom * fy;
            }
        }
    }
    return rgb;
}

}  // namespace

int main(int argc, char** argv) {
    const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
    const std::filesystem::path scratch =
        std::filesystem::temp_directory_path() / "candela_bench_ibl";
    std::filesystem::remove_all(scratch);
    std::filesystem::create_directories(scratch);

    content::Diagnostics diagnostics;
    const std::filesystem::path source =
        std::filesystem::path(CANDELA_SHARED_ASSETS) / "env/chinese_garden_1k.exr";
    std::optional<content::ExrImage> image = content::readExrImage(source, diagnostics);
    if (!image) {
        std::fprintf(stderr, "candela-bench-ibl: %s\n", diagnostics.toString().c_str());
        return 1;
    }
    const std::filesystem::path sky = scratch / "sky_2k.exr";
    std::vector<float> rgb = upsample(image->image, 2048, 1024);
    if (std::string e = content::writeExrRgbFloat(sky, 2048, 1024, rgb.data()); !e.empty()) {
        std::fprintf(stderr, "candela-bench-ibl: %s\n", e.c_str());
        return 1;
    }

    render::GpuContext context({});
    std::vector<double> first, firstPrecompute, firstDecode, firstCacheWrite, cached, lut;
    render::EnvironmentBuildStats shape;
    for (int i = 0; i < runs; ++i) {
        render::EnvironmentCacheOptions cache{scratch / ("cache" + std::to_string(i))};
        content::Diagnostics d;
        auto start = std::chrono::steady_clock::now();
        auto env = render::Environment::load(context, sky, d, cache);
        first.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count());
        firstPrecompute.push_back(env->stats().precomputeMs);
        firstDecode.push_back(env->stats().decodeMs);
        firstCacheWrite.push_back(env->stats().cacheMs);
        shape = env->stats();
        start = std::chrono::steady_clock::now();
        auto again = render::Environment::load(context, sky, d, cache);
        cached.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count());
        if (!again->stats().fromCache) std::fprintf(stderr, "warning: cache miss on run %d\n", i);
        render::EnvironmentBrdfLut brdf(context);
        lut.push_back(brdf.buildMs());
    }
    std::printf("device: %s, %d runs, medians\n", context.deviceName().c_str(), runs);
    std::printf("2048x1024 lat-long -> cube %u^2 x %u mips, prefiltered %u^2 x %u roughness mips\n",
                shape.cubeFaceSize, unsigned(std::bit_width(shape.cubeFaceSize)),
                shape.prefilteredFaceSize, shape.prefilteredMipCount);
    std::printf("| step | ms |\n|---|---|\n");
    std::printf("| first run, total | %.0f |\n", median(first));
    std::printf("| - OpenEXR decode | %.0f |\n", median(firstDecode));
    std::printf("| - device precompute (cube, mips, prefilter, SH) | %.0f |\n",
                median(firstPrecompute));
    std::printf("| - cache write | %.0f |\n", median(firstCacheWrite));
    std::printf("| cached run, total | %.0f |\n", median(cached));
    std::printf("| environment BRDF LUT (once per renderer) | %.0f |\n", median(lut));
    std::filesystem::remove_all(scratch);
    return 0;
}
