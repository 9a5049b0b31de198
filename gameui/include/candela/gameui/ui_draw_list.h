#pragma once
// What the UI pass draws for a laid-out WidgetTree: textured, coloured triangles in window
// pixels, in the order widgets were added (children over parents), sampling the atlas (glyphs,
// images, and its white corner for solid fills) and multiplying by the vertex colour. Text is
// placed on whole pixels at whole pixel sizes, so glyphs keep FreeType's coverage exactly.
#include <array>
#include <cstdint>
#include <vector>

#include "candela/gameui/glyph_atlas.h"
#include "candela/gameui/widget_tree.h"

namespace candela::gameui {

struct UiVertex {
    float x, y;          // window pixels
    float u, v;          // atlas, 0..1
    std::uint32_t rgba;  // display-encoded, R in the low byte
};

struct UiDrawList {
    std::vector<UiVertex> vertices;
    std::vector<std::uint32_t> indices;

    void rect(const Rect& r, const std::array<float, 4>& color, float atlasSize);
    void clear() {
        vertices.clear();
        indices.clear();
    }
};

// Appends the tree's visible widgets: fills, images, text, slider knobs, list rows, the focus
// outline.
void buildDrawList(const WidgetTree& tree, const Font& font, GlyphAtlas& atlas, UiDrawList& out);

}  // namespace candela::gameui
