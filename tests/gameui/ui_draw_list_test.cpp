// What the UI pass is given: glyphs rasterised once, on whole pixels at one texel per pixel
// (crisp at every window size), fills sampling the atlas's covered corner, and the atlas
// starting again when full without a glyph placed before the reset.
#include <gtest/gtest.h>

#include <cmath>

#include <filesystem>
#include <fstream>

#include "candela/content/png_writer.h"
#include "candela/gameui/ui_draw_list.h"
#include "fallback_font.h"

namespace candela::gameui {
namespace {

const Font& font() {
    return test::fallbackFont();
}

TEST(UiDrawList, GlyphsSitOnWholePixelsOneTexelPerPixelAtEveryWindowSize) {
    WidgetTree ui;
    const WidgetId play =
        ui.add(button("Play again", {0.5f, 0.5f, 0.5f, 0.5f}, {-120, -30, 120, 30}));
    GlyphAtlas atlas(512);
    for (float height : {360.0f, 720.0f, 1080.0f}) {
        SCOPED_TRACE(height);
        ui.layout(height * 16 / 9, height);
        UiDrawList list;
        buildDrawList(ui, font(), atlas, list);
        // One fill, then a quad per visible glyph ("Play again": nine).
        ASSERT_EQ(list.indices.size(), 6u * 10u);
        const Rect& r = ui.rect(play);
        for (std::size_t q = 1; q < list.vertices.size() / 4; ++q) {
            const UiVertex& a = list.vertices[4 * q];
            const UiVertex& c = list.vertices[4 * q + 2];
            EXPECT_EQ(a.x, std::round(a.x));
            EXPECT_EQ(a.y, std::round(a.y));
            EXPECT_NEAR((c.x - a.x), (c.u - a.u) * 512.0f, 1e-3) << "one texel per pixel";
            EXPECT_NEAR((c.y - a.y), (c.v - a.v) * 512.0f, 1e-3);
            EXPECT_GE(a.x, r.x);
            EXPECT_LE(c.x, r.x + r.width);
        }
    }
    EXPECT_EQ(atlas.resets(), 0u);
}

TEST(UiDrawList, AFullAtlasStartsAgainAndTheListIsBuiltFromTheNewOne) {
    GlyphAtlas atlas(64);  // room for a few large glyphs only
    WidgetTree ui;
    ui.add(label("abcdefghijklmnopqrstuvwxyz", {0, 0, 1, 1}, {}));
    ui.layout(1280, 720);
    ui.widget(0).style.pixelSize = 30;
    UiDrawList list;
    buildDrawList(ui, font(), atlas, list);
    EXPECT_GE(atlas.resets(), 1u);
    // Every quad that was kept samples texels the atlas holds now.
    for (const UiVertex& v : list.vertices) {
        EXPECT_GE(v.u, 0.0f);
        EXPECT_LE(v.u, 1.0f);
    }
}

TEST(UiDrawList, HiddenWidgetsAndTransparentFillsDrawNothing) {
    WidgetTree ui;
    const WidgetId menu = ui.add(panel({0, 0, 1, 1}, {}));
    ui.add(button("Quit", {0, 0, 1, 1}, {10, 10, -10, -10}), menu);
    ui.layout(640, 360);
    GlyphAtlas atlas;
    UiDrawList shown, hidden;
    buildDrawList(ui, font(), atlas, shown);
    EXPECT_GT(shown.indices.size(), 12u);
    ui.widget(menu).visible = false;
    buildDrawList(ui, font(), atlas, hidden);
    EXPECT_TRUE(hidden.indices.empty());
}

}  // namespace
}  // namespace candela::gameui

namespace candela::gameui {
namespace {

// An image widget draws its PNG stretched over its rect from the atlas; a file that is not an
// image, or one too large for the atlas, is an error naming it, once, and draws nothing.
TEST(UiDrawList, ImagesDrawFromTheAtlasAndBadOnesAreNamedOnce) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "candela-ui-images";
    std::filesystem::create_directories(dir);
    std::vector<std::uint8_t> rgba(16 * 8 * 4);
    for (std::size_t i = 0; i < rgba.size(); i += 4) {
        rgba[i] = 200, rgba[i + 1] = 40, rgba[i + 2] = 10, rgba[i + 3] = 255;
    }
    ASSERT_EQ(content::writePng(dir / "icon.png", 16, 8, 4, rgba.data()), "");
    std::ofstream(dir / "notes.png") << "not an image";
    const std::vector<std::uint8_t> wide(600 * 2 * 4);
    ASSERT_EQ(content::writePng(dir / "huge.png", 600, 2, 4, wide.data()), "");
    WidgetTree ui;
    const WidgetId icon =
        ui.add(image((dir / "icon.png").string(), {0, 0, 0, 0}, {10, 10, 74, 42}));
    ui.add(image((dir / "notes.png").string(), {0, 0, 0, 0}, {100, 10, 164, 42}));
    ui.add(image((dir / "huge.png").string(), {0, 0, 0, 0}, {200, 10, 264, 42}));
    ui.layout(1280, 720);
    GlyphAtlas atlas(256);
    UiDrawList list;
    buildDrawList(ui, font(), atlas, list);
    ASSERT_EQ(list.vertices.size(), 4u) << "only the readable image";
    EXPECT_EQ(list.vertices[0].x, ui.rect(icon).x);
    EXPECT_EQ(list.vertices[2].x, ui.rect(icon).x + ui.rect(icon).width);
    // Its texels in the atlas are the image's (RGBA, row by row).
    const std::uint32_t u = std::uint32_t(list.vertices[0].u * 256.0f);
    const std::uint32_t v = std::uint32_t(list.vertices[0].v * 256.0f);
    EXPECT_EQ(atlas.pixels()[(v * 256 + u) * 4], 200);
    EXPECT_EQ(atlas.pixels()[(v * 256 + u) * 4 + 1], 40);
    content::Diagnostics first = atlas.takeDiagnostics();
    EXPECT_EQ(first.messages.size(), 2u) << first.toString();
    EXPECT_TRUE(first.mentions("cannot decode image")) << first.toString();
    EXPECT_TRUE(first.mentions("larger than a UI image")) << first.toString();
    list.clear();
    buildDrawList(ui, font(), atlas, list);
    EXPECT_TRUE(atlas.takeDiagnostics().messages.empty()) << "reported once";
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace candela::gameui
