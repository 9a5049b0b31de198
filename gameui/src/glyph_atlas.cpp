#include "candela/gameui/glyph_atlas.h"

#include <algorithm>

namespace candela::gameui {
namespace {

constexpr std::uint32_t kPadding = 1;  // empty texels between glyphs: linear filtering never bleeds

}  // namespace

GlyphAtlas::GlyphAtlas(std::uint32_t size) : size_(std::max(size, 64u)) {
    clear();
    resets_ = 0;
}

void GlyphAtlas::clear() {
    pixels_.assign(std::size_t(size_) * size_, 0);
    for (std::uint32_t y = 0; y < 2; ++y)
        for (std::uint32_t x = 0; x < 2; ++x)
            pixels_[y * size_ + x] = 255;  // the solid texels
    glyphs_.clear();
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

AtlasGlyph GlyphAtlas::glyph(const Font& font, std::uint32_t glyphIndex, std::uint32_t pixelSize) {
    const auto key = std::tuple{&font, glyphIndex, pixelSize};
    if (auto it = glyphs_.find(key); it != glyphs_.end()) return it->second;
    const GlyphBitmap bitmap = font.rasterize(glyphIndex, float(pixelSize));
    AtlasGlyph g;
    g.left = bitmap.left;
    g.top = bitmap.top;
    g.advance = bitmap.advance;
    if (bitmap.width > 0 && bitmap.height > 0) {
        // Full: start again empty; a glyph larger than the whole atlas draws as nothing.
        bool placed = reserve(bitmap.width, bitmap.height, g.x, g.y);
        if (!placed) {
            clear();
            placed = reserve(bitmap.width, bitmap.height, g.x, g.y);
        }
        if (placed) {
            g.width = bitmap.width;
            g.height = bitmap.height;
            for (std::uint32_t row = 0; row < bitmap.height; ++row) {
                std::copy_n(bitmap.coverage.begin() + std::ptrdiff_t(row * bitmap.width),
                            bitmap.width,
                            pixels_.begin() + std::ptrdiff_t((g.y + row) * size_ + g.x));
            }
            dirty_ = true;
        }
    }
    glyphs_.emplace(key, g);
    return g;
}

}  // namespace candela::gameui
