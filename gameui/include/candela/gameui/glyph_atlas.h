#pragma once
// Glyphs rasterised once into one 8-bit coverage image the UI pass samples, packed in shelves
// (rows as tall as their tallest glyph). Sizes are whole pixels, so a glyph drawn at its
// rasterised size maps texel to pixel and stays as crisp as FreeType drew it. The top-left 2x2
// texels are fully covered: solid rectangles sample them.
//
//   GlyphAtlas atlas;
//   AtlasGlyph g = atlas.glyph(*font, glyphIndex, 24);
//   if (atlas.dirty()) upload(atlas.pixels()), atlas.markUploaded();
#include <cstdint>
#include <map>
#include <tuple>
#include <vector>

#include "candela/gameui/font.h"

namespace candela::gameui {

struct AtlasGlyph {
    std::uint32_t x = 0, y = 0, width = 0, height = 0;  // texels in the atlas
    std::int32_t left = 0, top = 0;                     // from the pen, as GlyphBitmap
    float advance = 0;
};

class GlyphAtlas {
public:
    explicit GlyphAtlas(std::uint32_t size = 1024);

    // Rasterises on first use. When the atlas is full it starts again empty (every glyph is
    // rasterised anew as it is next asked for) and counts a reset: a caller that placed glyphs
    // before a reset places them again.
    AtlasGlyph glyph(const Font& font, std::uint32_t glyphIndex, std::uint32_t pixelSize);

    std::uint32_t size() const { return size_; }
    const std::vector<std::uint8_t>& pixels() const { return pixels_; }
    bool dirty() const { return dirty_; }
    void markUploaded() { dirty_ = false; }
    std::uint32_t resets() const { return resets_; }
    std::size_t glyphCount() const { return glyphs_.size(); }

private:
    void clear();
    bool reserve(std::uint32_t width, std::uint32_t height, std::uint32_t& x, std::uint32_t& y);

    std::uint32_t size_;
    std::vector<std::uint8_t> pixels_;
    std::map<std::tuple<const Font*, std::uint32_t, std::uint32_t>, AtlasGlyph> glyphs_;
    std::uint32_t shelfX_ = 0, shelfY_ = 0, shelfHeight_ = 0;
    bool dirty_ = true;
    std::uint32_t resets_ = 0;
};

}  // namespace candela::gameui
