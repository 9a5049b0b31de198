#pragma once
// Glyphs rasterised once, and interface images, in one RGBA8 image the UI pass samples,
// packed in shelves (rows as tall as their tallest entry). A glyph is white with its coverage
// as alpha; sizes are whole pixels, so a glyph drawn at its rasterised size maps texel to
// pixel and stays as crisp as FreeType drew it. The top-left 2x2 texels are opaque white: solid
// rectangles sample them.
//
//   GlyphAtlas atlas;
//   AtlasGlyph g = atlas.glyph(*font, glyphIndex, 24);
//   AtlasGlyph icon = atlas.image("ui/spark.png");  // width 0: not loaded (see diagnostics())
//   if (atlas.dirty()) upload(atlas.pixels()), atlas.markUploaded();
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "candela/content/diagnostics.h"
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
    // A PNG or JPEG, loaded on first use. One that cannot be read, or is over kMaxImageSize on
    // a side, has no texels (width 0) and an error in diagnostics(), once.
    AtlasGlyph image(const std::string& path);
    static constexpr std::uint32_t kMaxImageSize = 512;
    // Problems loading images since the last takeDiagnostics().
    content::Diagnostics takeDiagnostics();

    std::uint32_t size() const { return size_; }
    const std::vector<std::uint8_t>& pixels() const { return pixels_; }  // RGBA8, row-major
    bool dirty() const { return dirty_; }
    void markUploaded() { dirty_ = false; }
    std::uint32_t resets() const { return resets_; }
    std::size_t glyphCount() const { return glyphs_.size(); }

private:
    void clear();
    bool reserve(std::uint32_t width, std::uint32_t height, std::uint32_t& x, std::uint32_t& y);
    // Places `width` x `height` texels; `texel(x, y)` gives each one's RGBA.
    template <class Texel>
    bool place(AtlasGlyph& g, std::uint32_t width, std::uint32_t height, Texel texel);

    std::uint32_t size_;
    std::vector<std::uint8_t> pixels_;
    std::map<std::tuple<const Font*, std::uint32_t, std::uint32_t>, AtlasGlyph> glyphs_;
    std::map<std::string, AtlasGlyph> images_;
    std::set<std::string> failedImages_;  // reported once, never loaded again
    content::Diagnostics diagnostics_;
    std::uint32_t shelfX_ = 0, shelfY_ = 0, shelfHeight_ = 0;
    bool dirty_ = true;
    std::uint32_t resets_ = 0;
};

}  // namespace candela::gameui
