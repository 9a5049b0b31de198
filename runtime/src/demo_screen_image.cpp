#include "demo_screen_image.h"

#include <array>
#include <cstdint>

namespace candela::runtime {

std::shared_ptr<const content::Rgba8Image> demoScreenImage() {
    auto image = std::make_shared<content::Rgba8Image>();
    image->width = 128;
    image->height = 72;
    image->rgba.resize(size_t(image->width) * image->height * 4);
    // White, yellow, cyan, green, magenta, red, blue: the classic bars, 75 % sRGB.
    constexpr std::array<std::array<uint8_t, 3>, 7> kBars{{{191, 191, 191},
                                                           {191, 191, 0},
                                                           {0, 191, 191},
                                                           {0, 191, 0},
                                                           {191, 0, 191},
                                                           {191, 0, 0},
                                                           {0, 0, 191}}};
    for (uint32_t y = 0; y < image->height; ++y) {
        for (uint32_t x = 0; x < image->width; ++x) {
            uint8_t* texel = &image->rgba[(size_t(y) * image->width + x) * 4];
            const bool frame = x < 2 || y < 2 || x + 2 >= image->width || y + 2 >= image->height;
            if (frame) {
                texel[0] = texel[1] = texel[2] = 255;
            } else if (y < image->height * 2 / 3) {
                const auto& bar = kBars[x * kBars.size() / image->width];
                texel[0] = bar[0], texel[1] = bar[1], texel[2] = bar[2];
            } else {
                texel[0] = texel[1] = texel[2] = uint8_t(x * 255 / (image->width - 1));
            }
            texel[3] = 255;
        }
    }
    return image;
}

}  // namespace candela::runtime
