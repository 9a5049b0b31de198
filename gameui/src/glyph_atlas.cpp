#include "candela/gameui/glyph_atlas.h"

#include <algorithm>
#include <array>
#include <optional>
#include <utility>

#include "candela/content/image_file.h"

namespace candela::gameui {
namespace {

constexpr std::uint32_t kPadding = 1;  // empty texels between glyphs: linear filtering never bleeds

}  // namespace

GlyphAtlas::GlyphAtlas(std::uint32_t size) : size_(std::max(size, 64u)) {
    clear();
    resets_ = 0;
}

void GlyphAtlas::clear() {
    pixels_.assign(std::size_t(size_) * size_ * 4, 0);
    for (std::uint32_t y = 0; y < 2; ++y)
        for (std::uint32_t x = 0; x < 2; ++x)
            std::fill_n(pixels_.begin() + std::ptrdiff_t((y * size_ + x) * 4), 4, 255);  // solid
    glyphs_.clear();
    images_.clear();  // placed again when next drawn
    shelfX_ = 2 + kPadding;
    shelfY_ = 0;
    shelfHeight_ = 2;
    dirty_ = true;
    ++resets_;
}

bool GlyphAtlas::reserve(std::uint32_t width, std::uint32_t height, std::uint32_t& x,
                         std::uint32_t& y) {
    if (shelfX_ + width + kPadding > size_) {  // the next shelf
        shelfY_ += shelfHeight_ + kPadding;
        shelfX_ = 0;
        shelfHeight_ = 0;
    }
    if (shelfX_ + width + kPadding > size_ || shelfY_ + height + kPadding > size_) return false;
    x = shelfX_;
    y = shelfY_;
    shelfX_ += width + kPadding;
    shelfHeight_ = std::max(shelfHeight_, height);
    return true;
}

template <class Texel>
bool GlyphAtlas::place(AtlasGlyph& g, std::uint32_t width, std::uint32_t height, Texel texel) {
    // Full: start again empty; an entry larger than the whole atlas has no texels.
    bool placed = reserve(width, height, g.x, g.y);
    if (!placed) {
        clear();
        placed = reserve(width, height, g.x, g.y);
    }
    if (!placed) return false;
    g.width = width;
    g.height = height;
    for (std::uint32_t row = 0; row < height; ++row) {
        for (std::uint32_t column = 0; column < width; ++column) {
            const std::array<std::uint8_t, 4> rgba = texel(column, row);
            std::copy(rgba.begin(), rgba.end(),
                      pixels_.begin() + std::ptrdiff_t(((g.y + row) * size_ + g.x + column) * 4));
        }
    }
    dirty_ = true;
    return true;
}

AtlasGlyph GlyphAtlas::glyph(const Font& font, std::uint32_t glyphIndex, std::uint32_t pixelSize) {
    const auto key = std::tuple{&font, glyphIndex, pixelSize};
    if (auto it = glyphs_.find(key); it != glyphs_.end()) return it->second;
    const GlyphBitmap bitmap = font.rasterize(glyphIndex, float(pixelSize));
    AtlasGlyph g;
    g.left = bitmap.left;
    g.top = bitmap.top;
    g.advance = bitmap.advance;
    if (bitmap.width > 0 && bitmap.height > 0) {
        place(g, bitmap.width, bitmap.height, [&](std::uint32_t x, std::uint32_t y) {
            const std::uint8_t coverage = bitmap.coverage[y * bitmap.width + x];
            return std::array<std::uint8_t, 4>{255, 255, 255, coverage};
        });
    }
    glyphs_.emplace(key, g);
    return g;
}

AtlasGlyph GlyphAtlas::image(const std::string& path) {
    if (auto it = images_.find(path); it != images_.end()) return it->second;
    if (failedImages_.contains(path)) return {};
    std::optional<content::Rgba8Image> loaded = content::loadImageFile(path, diagnostics_);
    if (!loaded) {
        failedImages_.insert(path);
        return {};
    }
    const content::Rgba8Image pixels = std::move(*loaded);
    if (pixels.width > kMaxImageSize || pixels.height > kMaxImageSize) {
        diagnostics_.error(path, "",
                           std::to_string(pixels.width) + "x" + std::to_string(pixels.height) +
                               " is larger than a UI image may be (" +
                               std::to_string(kMaxImageSize) + " on a side); it is not drawn");
        failedImages_.insert(path);
        return {};
    }
    AtlasGlyph g;
    place(g, pixels.width, pixels.height, [&](std::uint32_t x, std::uint32_t y) {
        const std::size_t at = (std::size_t(y) * pixels.width + x) * 4;
        return std::array<std::uint8_t, 4>{pixels.rgba[at], pixels.rgba[at + 1],
                                           pixels.rgba[at + 2], pixels.rgba[at + 3]};
    });
    images_[path] = g;
    return g;
}

content::Diagnostics GlyphAtlas::takeDiagnostics() {
    return std::exchange(diagnostics_, {});
}

}  // namespace candela::gameui
