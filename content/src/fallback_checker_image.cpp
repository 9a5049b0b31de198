#include "candela/content/image.h"

namespace candela::content {

Rgba8Image makeFallbackCheckerImage() {
    constexpr std::uint32_t kSize = 8;
    Rgba8Image image;
    image.width = kSize;
    image.height = kSize;
    image.isFallback = true;
    image.rgba.resize(kSize * kSize * 4);
    for (std::uint32_t y = 0; y < kSize; ++y) {
        for (std::uint32_t x = 0; x < kSize; ++x) {
            const bool magenta = ((x / 2) + (y / 2)) % 2 == 0;  // 2x2-texel cells
            std::uint8_t* t = &image.rgba[(y * kSize + x) * 4];
            t[0] = magenta ? 255 : 0;
            t[1] = 0;
            t[2] = magenta ? 255 : 0;
            t[3] = 255;
        }
    }
    return image;
}

}  // namespace candela::content
