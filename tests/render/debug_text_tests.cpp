// The debug text's font and layout, without a device: every glyph is distinct, characters land
// where the metrics say, lines break on '\n', and text off the image costs nothing.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "passes/debug_text/bitmap_font.h"
#include "passes/debug_text/debug_text_pass.h"

using namespace candela::render;

namespace {

std::string drawn(std::uint32_t glyph) {
    std::string art;
    for (int row = 0; row < 7; ++row) {
        for (int column = 0; column < 5; ++column)
            art += glyphInked(glyph, column, row) ? '#' : '.';
        art += '\n';
    }
    return art;
}

}  // namespace

TEST(DebugText, EveryGlyphIsDistinctAndLowerCaseDrawsAsUpperCase) {
    std::set<std::string> seen;
    for (std::uint32_t g = 0; g < fontGlyphs().size(); ++g)
        EXPECT_TRUE(seen.insert(drawn(g)).second) << "glyph " << g << " repeats:\n" << drawn(g);
    EXPECT_EQ(glyphIndex('s'), glyphIndex('S'));
    EXPECT_NE(glyphIndex('S'), glyphIndex('5'));
    EXPECT_EQ(glyphIndex('~'), glyphIndex('\x01')) << "characters without a glyph share the box";
    EXPECT_EQ(drawn(glyphIndex('~')), "#####\n#...#\n#...#\n#...#\n#...#\n#...#\n#####\n");
    EXPECT_EQ(drawn(glyphIndex('1')), "..#..\n.##..\n..#..\n..#..\n..#..\n..#..\n.###.\n");
    EXPECT_FALSE(glyphInked(glyphIndex('1'), 5, 0)) << "outside the 5x7 cell";
}

TEST(DebugText, LayoutFollowsTheMetricsAndBreaksLines) {
    TextLine line;
    line.x = 10;
    line.y = 20;
    line.scale = 3;
    line.color = {1.0f, 0.5f, 0.25f};
    line.text = "A B\nCD";
    const std::vector<GlyphInstance> glyphs = layoutText({&line, 1}, 640, 480, 100);
    ASSERT_EQ(glyphs.size(), 4u) << "the space draws nothing";
    EXPECT_EQ(glyphs[0].x, 10);
    EXPECT_EQ(glyphs[1].x, 10 + 2 * kTextAdvance * 3);
    EXPECT_EQ(glyphs[2].x, 10);
    EXPECT_EQ(glyphs[2].y, 20 + kTextLineAdvance * 3);
    EXPECT_EQ(glyphs[3].x, 10 + kTextAdvance * 3);
    EXPECT_EQ(glyphs[3].index, glyphIndex('D'));
    EXPECT_EQ(glyphs[0].scale, 3u);
    EXPECT_EQ(glyphs[0].color[1], 0.5f);
}

TEST(DebugText, OffImageTextIsDroppedAndScaleAndCountAreBounded) {
    TextLine off{-1000, 5, 1, {1, 1, 1}, "HIDDEN"};
    TextLine below{5, 200, 1, {1, 1, 1}, "X"};
    TextLine huge{0, 0, 99, {1, 1, 1}, "W"};
    const TextLine lines[] = {off, below, huge};
    const std::vector<GlyphInstance> glyphs = layoutText(lines, 100, 100, 100);
    ASSERT_EQ(glyphs.size(), 1u);
    EXPECT_EQ(glyphs[0].scale, kTextMaxScale);
    TextLine edge{2147483600, 2147483600, 8, {1, 1, 1}, "FAR\nAWAY"};  // no overflow
    EXPECT_TRUE(layoutText({&edge, 1}, 100, 100, 100).empty());
    TextLine many{0, 0, 1, {1, 1, 1}, std::string(500, 'M')};
    EXPECT_EQ(layoutText({&many, 1}, 4096, 100, 64).size(), 64u);
}
