#pragma once
// A font file (TrueType or OpenType, through FreeType) and its glyphs rasterised at a pixel
// size. FreeType is made to read fonts it did not write, so a truncated or hostile file is an
// error, never a crash. A file that is not a font is an error naming it; games then use the
// fallback font (DejaVu Sans, Debian's fonts-dejavu-core).
//
//   content::Diagnostics diagnostics;
//   std::shared_ptr<const Font> font = Font::load("fonts/title.ttf", diagnostics);
//   if (!font) font = Font::fallback(diagnostics);
#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

#include "candela/content/diagnostics.h"

namespace candela::gameui {

// Where the fallback font is looked for (fonts-dejavu-core installs it).
inline constexpr const char* kFallbackFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
inline constexpr std::uint64_t kMaxFontFileBytes = 64ull * 1024 * 1024;

struct LineMetrics {
    float ascent = 0;      // pixels above the baseline
    float descent = 0;     // pixels below it (positive)
    float lineHeight = 0;  // baseline to baseline
};

// One glyph's coverage, 8 bits a pixel, and where it sits: its top-left corner is `left`
// pixels right of the pen and `top` pixels above the baseline.
struct GlyphBitmap {
    std::uint32_t width = 0, height = 0;
    std::int32_t left = 0, top = 0;
    float advance = 0;  // pixels the pen moves on
    std::vector<std::uint8_t> coverage;
};

class Font {
public:
    static std::shared_ptr<const Font> load(const std::filesystem::path& path,
                                            content::Diagnostics& diagnostics);
    // DejaVu Sans, loaded once; null (with an error) only when the package is missing.
    static std::shared_ptr<const Font> fallback(content::Diagnostics& diagnostics);
    ~Font();
    Font(const Font&) = delete;
    Font& operator=(const Font&) = delete;

    // 0 when the font has no glyph for the code point (its .notdef box is drawn).
    std::uint32_t glyphIndex(char32_t codepoint) const;
    LineMetrics lineMetrics(float pixelSize) const;
    // Pixels to add between two glyphs' advances (negative: closer), 0 without kerning.
    float kerning(std::uint32_t left, std::uint32_t right, float pixelSize) const;
    // Pixels the pen moves on after the glyph (what rasterize() reports, without drawing).
    float advance(std::uint32_t glyph, float pixelSize) const;
    GlyphBitmap rasterize(std::uint32_t glyph, float pixelSize) const;
    const std::filesystem::path& path() const { return path_; }

private:
    Font();
    struct Impl;
    std::unique_ptr<Impl> impl_;
    std::filesystem::path path_;
};

}  // namespace candela::gameui
