#include "candela/gameui/text_layout.h"

#include <algorithm>

#include "candela/gameui/utf8.h"

namespace candela::gameui {
namespace {

struct Shaped {
    char32_t codepoint;
    std::uint32_t glyph;
    float advance;
    float kern;  // with the glyph before it
};

std::vector<Shaped> shape(const Font& font, const std::u32string& text, float size) {
    std::vector<Shaped> out;
    out.reserve(text.size());
    for (char32_t c : text) {
        const std::uint32_t glyph = font.glyphIndex(c);
        const float kern = out.empty() ? 0.0f : font.kerning(out.back().glyph, glyph, size);
        out.push_back({c, glyph, font.advance(glyph, size), kern});
    }
    return out;
}

// One line of a paragraph: glyphs [begin, end), trailing spaces already left out.
struct Line {
    std::size_t begin, end;
    float width;
};

float widthOf(const std::vector<Shaped>& g, std::size_t begin, std::size_t end) {
    float width = 0;
    for (std::size_t i = begin; i < end; ++i)
        width += g[i].advance + (i > begin ? g[i].kern : 0.0f);
    return width;
}

// Greedy: as many words as fit; the break goes at the last space, or between letters when one
// word is wider than the box. Spaces at a break belong to neither line.
std::vector<Line> breakLines(const std::vector<Shaped>& g, float maxWidth) {
    std::vector<Line> lines;
    std::size_t start = 0;
    do {
        float width = 0;
        std::size_t i = start, lastSpace = start;
        for (; i < g.size(); ++i) {
            const float w = g[i].advance + (i > start ? g[i].kern : 0.0f);
            if (g[i].codepoint == U' ') lastSpace = i;
            if (maxWidth > 0 && width + w > maxWidth && i > start && g[i].codepoint != U' ') break;
            width += w;
        }
        std::size_t end = i, next = i;
        if (i < g.size()) {
            end = lastSpace > start ? lastSpace : i;
            next = end;
            while (next < g.size() && g[next].codepoint == U' ')
                ++next;
        }
        std::size_t trimmed = end;
        while (trimmed > start && g[trimmed - 1].codepoint == U' ')
            --trimmed;
        lines.push_back({start, trimmed, widthOf(g, start, trimmed)});
        start = next;
    } while (start < g.size());
    return lines;
}

}  // namespace

TextLayout layoutText(const Font& font, std::string_view utf8, const TextStyle& style,
                      float maxWidth) {
    TextLayout out;
    if (utf8.empty()) return out;
    const std::u32string text = decodeUtf8(utf8);
    const LineMetrics metrics = font.lineMetrics(style.pixelSize);
    const float lineStep = metrics.lineHeight * style.lineSpacing;
    // Paragraphs at '\n'; each is shaped and broken on its own.
    std::vector<std::vector<Shaped>> paragraphs;
    struct Placed {
        std::size_t paragraph;
        Line line;
    };
    std::vector<Placed> lines;
    std::size_t from = 0;
    while (from <= text.size()) {
        const std::size_t to = std::min(text.find(U'\n', from), text.size());
        paragraphs.push_back(shape(font, text.substr(from, to - from), style.pixelSize));
        for (const Line& line : breakLines(paragraphs.back(), maxWidth))
            lines.push_back({paragraphs.size() - 1, line});
        from = to + 1;
    }
    for (const Placed& p : lines)
        out.width = std::max(out.width, p.line.width);
    const float boxWidth = maxWidth > 0 ? maxWidth : out.width;
    for (std::size_t k = 0; k < lines.size(); ++k) {
        const Placed& p = lines[k];
        const float slack = boxWidth - p.line.width;
        float x = style.align == TextAlign::Left     ? 0.0f
                  : style.align == TextAlign::Center ? slack / 2
                                                     : slack;
        const float baseline = metrics.ascent + float(k) * lineStep;
        for (std::size_t i = p.line.begin; i < p.line.end; ++i) {
            const Shaped& g = paragraphs[p.paragraph][i];
            if (i > p.line.begin) x += g.kern;
            if (g.codepoint != U' ') out.glyphs.push_back({g.glyph, g.codepoint, x, baseline});
            x += g.advance;
        }
        out.lineWidths.push_back(p.line.width);
    }
    out.height = metrics.ascent + metrics.descent + float(lines.size() - 1) * lineStep;
    return out;
}

}  // namespace candela::gameui
