#include "candela/gameui/ui_draw_list.h"

#include <algorithm>
#include <cmath>

namespace candela::gameui {
namespace {

constexpr std::array<float, 4> kFocusColor{1.0f, 0.82f, 0.3f, 1.0f};

std::uint32_t packed(const std::array<float, 4>& c) {
    std::uint32_t out = 0;
    for (int i = 0; i < 4; ++i) {
        const auto byte = std::uint32_t(std::lround(std::clamp(c[i], 0.0f, 1.0f) * 255.0f));
        out |= byte << (8 * i);
    }
    return out;
}

std::array<float, 4> scaled(std::array<float, 4> c, float factor) {
    for (int i = 0; i < 3; ++i)
        c[i] = std::min(1.0f, c[i] * factor);
    return c;
}

void quad(UiDrawList& out, float x0, float y0, float x1, float y1, float u0, float v0, float u1,
          float v1, std::uint32_t rgba) {
    const auto base = std::uint32_t(out.vertices.size());
    out.vertices.push_back({x0, y0, u0, v0, rgba});
    out.vertices.push_back({x1, y0, u1, v0, rgba});
    out.vertices.push_back({x1, y1, u1, v1, rgba});
    out.vertices.push_back({x0, y1, u0, v1, rgba});
    for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u})
        out.indices.push_back(base + i);
}

// `text` laid out in `box` at the tree's scale, centred vertically; glyphs on whole pixels.
void text(UiDrawList& out, const std::string& s, TextStyle style, const Rect& box, float scale,
          const std::array<float, 4>& color, const Font& font, GlyphAtlas& atlas) {
    if (s.empty() || color[3] <= 0.0f) return;
    const auto pixelSize = std::uint32_t(std::max(1.0f, std::round(style.pixelSize * scale)));
    style.pixelSize = float(pixelSize);
    const TextLayout layout = layoutText(font, s, style, box.width);
    const float top = std::round(box.y + (box.height - layout.height) / 2);
    const float size = float(atlas.size());
    const std::uint32_t rgba = packed(color);
    for (const PlacedGlyph& g : layout.glyphs) {
        const AtlasGlyph a = atlas.glyph(font, g.glyph, pixelSize);
        if (a.width == 0) continue;
        const float x = std::round(box.x + g.x) + float(a.left);
        const float y = top + std::round(g.baseline) - float(a.top);
        quad(out, x, y, x + float(a.width), y + float(a.height), float(a.x) / size,
             float(a.y) / size, float(a.x + a.width) / size, float(a.y + a.height) / size, rgba);
    }
}

void outline(UiDrawList& out, const Rect& r, float width, const std::array<float, 4>& color,
             float atlasSize) {
    out.rect({r.x - width, r.y - width, r.width + 2 * width, width}, color, atlasSize);
    out.rect({r.x - width, r.y + r.height, r.width + 2 * width, width}, color, atlasSize);
    out.rect({r.x - width, r.y, width, r.height}, color, atlasSize);
    out.rect({r.x + r.width, r.y, width, r.height}, color, atlasSize);
}

void widget(UiDrawList& out, const WidgetTree& tree, WidgetId id, const Font& font,
            GlyphAtlas& atlas) {
    const Widget& w = tree.widget(id);
    const Rect& r = tree.rect(id);
    const float scale = tree.scale();
    const float size = float(atlas.size());
    const std::array<float, 4> textColor =
        w.enabled ? w.textColor
                  : std::array<float, 4>{w.textColor[0], w.textColor[1], w.textColor[2],
                                         w.textColor[3] * 0.5f};
    switch (w.kind) {
        case WidgetKind::Panel:
        case WidgetKind::Label:
            out.rect(r, w.color, size);
            text(out, w.text, w.style, r, scale, textColor, font, atlas);
            break;
        case WidgetKind::Image: {
            const AtlasGlyph a = atlas.image(w.image);
            if (a.width == 0) break;
            // Half a texel in from each edge: linear filtering never reaches the neighbours.
            quad(out, r.x, r.y, r.x + r.width, r.y + r.height, (float(a.x) + 0.5f) / size,
                 (float(a.y) + 0.5f) / size, (float(a.x + a.width) - 0.5f) / size,
                 (float(a.y + a.height) - 0.5f) / size, packed(w.color));
            break;
        }
        case WidgetKind::Button: {
            const float shade = tree.pressed() == id ? 0.8f : tree.hovered() == id ? 1.25f : 1.0f;
            out.rect(r, scaled(w.color, shade), size);
            text(out, w.text, w.style, r, scale, textColor, font, atlas);
            break;
        }
        case WidgetKind::Slider: {
            const float t =
                w.maximum > w.minimum ? (w.value - w.minimum) / (w.maximum - w.minimum) : 0.0f;
            const Rect track{r.x, r.y + r.height * 0.4f, r.width, r.height * 0.2f};
            out.rect(track, w.color, size);
            out.rect({track.x, track.y, track.width * t, track.height}, scaled(w.color, 2.0f),
                     size);
            const float knob = r.height * 0.6f;
            out.rect({r.x + t * r.width - knob / 2, r.y + r.height * 0.2f, knob, knob}, w.textColor,
                     size);
            break;
        }
        case WidgetKind::List: {
            out.rect(r, w.color, size);
            const float row = listRowHeight(w, scale);
            const float pad = 0.5f * w.style.pixelSize * scale;
            for (std::size_t i = 0; i < w.items.size(); ++i) {
                const Rect line{r.x + pad, r.y + row * float(i), r.width - 2 * pad, row};
                if (line.y + row > r.y + r.height) break;  // rows past the box are not drawn
                if (std::int32_t(i) == w.selected)
                    out.rect({r.x, line.y, r.width, row}, scaled(w.color, 2.5f), size);
                text(out, w.items[i], w.style, line, scale, textColor, font, atlas);
            }
            break;
        }
    }
    if (tree.focused() == id)
        outline(out, r, std::max(1.0f, std::round(2.0f * scale)), kFocusColor, size);
}

}  // namespace

void UiDrawList::rect(const Rect& r, const std::array<float, 4>& color, float atlasSize) {
    if (color[3] <= 0.0f || r.width <= 0.0f || r.height <= 0.0f) return;
    // The atlas's covered 2x2 corner: its centre texel sample is 1 under any filter.
    const float solid = 1.0f / atlasSize;
    quad(*this, r.x, r.y, r.x + r.width, r.y + r.height, solid, solid, solid, solid, packed(color));
}

void buildDrawList(const WidgetTree& tree, const Font& font, GlyphAtlas& atlas, UiDrawList& out) {
    // A glyph placed before the atlas started again would sample emptied texels: build again.
    for (int attempt = 0; attempt < 2; ++attempt) {
        const std::uint32_t resets = atlas.resets();
        const std::size_t vertices = out.vertices.size(), indices = out.indices.size();
        for (WidgetId id = 0; id < tree.size(); ++id) {
            if (tree.shown(id)) widget(out, tree, id, font, atlas);
        }
        if (atlas.resets() == resets) return;
        out.vertices.resize(vertices);
        out.indices.resize(indices);
    }
}

}  // namespace candela::gameui
