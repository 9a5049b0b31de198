// Text in a box: wrapping at spaces, between letters when a word is too wide, '\n', alignment,
// and sizes that scale the whole layout.
#include <gtest/gtest.h>

#include <algorithm>

#include "candela/gameui/text_layout.h"
#include "candela/gameui/utf8.h"
#include "fallback_font.h"

namespace candela::gameui {
namespace {

const Font& font() {
    return test::fallbackFont();
}

int lineCount(const TextLayout& layout) {
    return int(layout.lineWidths.size());
}

TEST(TextLayout, ShortTextIsOneLineAndSpacesAreNotGlyphs) {
    const TextLayout t = layoutText(font(), "Press start", {.pixelSize = 20}, 0.0f);
    EXPECT_EQ(lineCount(t), 1);
    EXPECT_EQ(t.glyphs.size(), 10u);
    for (std::size_t i = 1; i < t.glyphs.size(); ++i)
        EXPECT_GT(t.glyphs[i].x, t.glyphs[i - 1].x) << "pens move right";
    EXPECT_GT(t.width, 80.0f);
    EXPECT_NEAR(t.height, font().lineMetrics(20).ascent + font().lineMetrics(20).descent, 1e-3);
}

TEST(TextLayout, WrapsAtSpacesToFitTheBoxAndAtLettersWhenAWordCannotFit) {
    const TextStyle style{.pixelSize = 20};
    // A box just wide enough for the first two words.
    const float box = layoutText(font(), "collect every", style, 0.0f).width + 1.0f;
    const TextLayout wrapped = layoutText(font(), "collect every spark", style, box);
    EXPECT_EQ(lineCount(wrapped), 2);
    for (float w : wrapped.lineWidths)
        EXPECT_LE(w, box);
    // The second line starts at the box's left with the word that did not fit.
    const auto second =
        std::find_if(wrapped.glyphs.begin(), wrapped.glyphs.end(),
                     [&](const PlacedGlyph& g) { return g.baseline > wrapped.glyphs[0].baseline; });
    ASSERT_NE(second, wrapped.glyphs.end());
    EXPECT_EQ(second->codepoint, U's');
    EXPECT_LT(second->x, 3.0f);
    const TextLayout narrow = layoutText(font(), "unbreakable", style, 30.0f);
    EXPECT_GE(lineCount(narrow), 3);
    for (float w : narrow.lineWidths)
        EXPECT_LE(w, 30.0f);
    EXPECT_EQ(narrow.glyphs.size(), 11u) << "no letter lost";
}

TEST(TextLayout, NewlinesStartLinesAndLinesAlign) {
    const TextStyle left{.pixelSize = 16};
    TextStyle centre = left, right = left;
    centre.align = TextAlign::Center;
    right.align = TextAlign::Right;
    const std::string text = "score\n120";
    const TextLayout l = layoutText(font(), text, left, 200.0f);
    const TextLayout c = layoutText(font(), text, centre, 200.0f);
    const TextLayout r = layoutText(font(), text, right, 200.0f);
    ASSERT_EQ(lineCount(l), 2);
    EXPECT_NEAR(l.glyphs.back().baseline - l.glyphs.front().baseline,
                font().lineMetrics(16).lineHeight, 1e-3);
    // Line 2 ("120") starts at 0, at (200 - w) / 2 and at 200 - w.
    const float w = l.lineWidths[1];
    const auto firstOfLine2 = [](const TextLayout& t) { return t.glyphs[5].x; };
    EXPECT_NEAR(firstOfLine2(l), 0.0f, 1e-3);
    EXPECT_NEAR(firstOfLine2(c), (200.0f - w) / 2, 1e-3);
    EXPECT_NEAR(firstOfLine2(r), 200.0f - w, 1e-3);
}

TEST(TextLayout, DoublingTheSizeDoublesTheLayout) {
    const std::string text = "Sparks: 3/8 \u2014 d\u00E9j\u00E0 vu";
    const TextLayout a = layoutText(font(), text, {.pixelSize = 18}, 0.0f);
    const TextLayout b = layoutText(font(), text, {.pixelSize = 36}, 0.0f);
    ASSERT_EQ(a.glyphs.size(), b.glyphs.size());
    EXPECT_NEAR(b.width / a.width, 2.0, 0.06);
    EXPECT_NEAR(b.height / a.height, 2.0, 0.06);
}

TEST(TextLayout, MalformedTextLaysOutWithReplacementGlyphs) {
    const TextLayout t = layoutText(font(), "ok\xFF\xFE!", {.pixelSize = 16}, 0.0f);
    EXPECT_EQ(t.glyphs.size(), 5u);
    EXPECT_EQ(t.glyphs[2].codepoint, kReplacementCharacter);
    EXPECT_TRUE(layoutText(font(), "", {}, 100.0f).glyphs.empty());
}

}  // namespace
}  // namespace candela::gameui
