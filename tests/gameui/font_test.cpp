// Fonts through FreeType: the fallback font renders crisp glyphs at every size, and a file that
// is not a font (or a damaged one) is an error naming it.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "candela/gameui/font.h"

namespace candela::gameui {
namespace {

std::shared_ptr<const Font> fallbackFont() {
    content::Diagnostics diagnostics;
    auto font = Font::fallback(diagnostics);
    EXPECT_TRUE(font) << diagnostics.toString();
    return font;
}

TEST(Font, TheFallbackFontHasLowerCaseAndAccentsAndScales) {
    const auto font = fallbackFont();
    ASSERT_TRUE(font);
    for (char32_t c : {U'a', U'z', U'A', U'\u00E9', U'0'})
        EXPECT_NE(font->glyphIndex(c), 0u) << std::uint32_t(c);
    const LineMetrics small = font->lineMetrics(16.0f), large = font->lineMetrics(48.0f);
    EXPECT_GT(small.ascent, 10.0f);
    EXPECT_NEAR(large.lineHeight / small.lineHeight, 3.0, 0.1);
    const GlyphBitmap x16 = font->rasterize(font->glyphIndex(U'x'), 16.0f);
    const GlyphBitmap x48 = font->rasterize(font->glyphIndex(U'x'), 48.0f);
    EXPECT_NEAR(double(x48.height) / x16.height, 3.0, 0.4);
    EXPECT_NEAR(x48.advance / x16.advance, 3.0, 0.2);
}

// Crisp: across a vertical stem's edge the coverage goes from empty to full within one pixel
// of grey, at both sizes (light hinting snaps horizontal edges; a blurred atlas would not).
TEST(Font, GlyphEdgesAreAtMostOnePixelOfGrey) {
    const auto font = fallbackFont();
    ASSERT_TRUE(font);
    for (float size : {16.0f, 40.0f}) {
        SCOPED_TRACE(size);
        const GlyphBitmap l = font->rasterize(font->glyphIndex(U'l'), size);
        ASSERT_GT(l.width * l.height, 0u);
        // The middle row of the 'l' stem: count the partially covered pixels on each side.
        const std::uint32_t y = l.height / 2;
        int grey = 0, full = 0;
        for (std::uint32_t x = 0; x < l.width; ++x) {
            const std::uint8_t c = l.coverage[y * l.width + x];
            grey += c > 16 && c < 240;
            full += c >= 240;
        }
        EXPECT_GE(full, 1) << "a solid stem";
        EXPECT_LE(grey, 2) << "at most one grey pixel each side";
    }
}

TEST(Font, AFileThatIsNotAFontIsAnErrorNamingIt) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "candela-fonts";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "notes.ttf") << "these are not glyphs";
    {
        std::ifstream real(kFallbackFontPath, std::ios::binary);
        std::string bytes{std::istreambuf_iterator<char>(real), {}};
        bytes.resize(bytes.size() / 8);  // the tables are there, their glyphs cut off
        std::ofstream(dir / "cut.ttf", std::ios::binary) << bytes;
    }
    for (const char* name : {"notes.ttf", "cut.ttf", "missing.ttf"}) {
        SCOPED_TRACE(name);
        content::Diagnostics diagnostics;
        EXPECT_FALSE(Font::load(dir / name, diagnostics));
        ASSERT_EQ(diagnostics.messages.size(), 1u) << diagnostics.toString();
        EXPECT_EQ(diagnostics.messages[0].file, (dir / name).string());
        EXPECT_TRUE(diagnostics.mentions("fallback font")) << diagnostics.toString();
    }
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace candela::gameui
