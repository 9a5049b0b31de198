#include "candela/gameui/font.h"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <map>
#include <mutex>
#include <string>

#include "candela/content/file_bytes.h"

namespace candela::gameui {

// FreeType's state (the size set, the glyph slot) changes with every call: one lock a font.
struct Font::Impl {
    FT_Library library = nullptr;
    FT_Face face = nullptr;
    std::vector<std::byte> bytes;  // FreeType reads the face from here, so it lives as long
    mutable std::mutex mutex;
    // Advances by (glyph, size in 26.6): every frame's layout asks for the same few, and each
    // uncached one loads the glyph's outline.
    mutable std::map<std::pair<std::uint32_t, FT_F26Dot6>, float> advances;

    ~Impl() {
        if (face) FT_Done_Face(face);
        if (library) FT_Done_FreeType(library);
    }
    // Pixel sizes as FreeType's 26.6 fixed point at 72 dpi (a point is then a pixel).
    bool setSize(float pixelSize) const {
        const auto size = static_cast<FT_F26Dot6>(pixelSize * 64.0f + 0.5f);
        return size > 0 && FT_Set_Char_Size(face, 0, size, 72, 72) == 0;
    }
};

Font::Font() : impl_(std::make_unique<Impl>()) {}
Font::~Font() = default;

std::shared_ptr<const Font> Font::load(const std::filesystem::path& path,
                                       content::Diagnostics& diagnostics) {
    const auto fail = [&](const std::string& problem) {
        diagnostics.error(path.string(), "", problem + "; the fallback font is used");
        return nullptr;
    };
    content::FileBytes file = content::readFileBytes(path, kMaxFontFileBytes);
    if (!file.error.empty()) return fail("cannot read font: " + file.error);
    std::shared_ptr<Font> font(new Font());
    Impl& f = *font->impl_;
    font->path_ = path;
    f.bytes = std::move(file.bytes);
    if (FT_Init_FreeType(&f.library) != 0) return fail("FreeType could not start");
    const FT_Error opened =
        FT_New_Memory_Face(f.library, reinterpret_cast<const FT_Byte*>(f.bytes.data()),
                           static_cast<FT_Long>(f.bytes.size()), 0, &f.face);
    if (opened != 0) {
        f.face = nullptr;
        return fail("not a font FreeType can read (error " + std::to_string(opened) + ")");
    }
    if (!FT_IS_SCALABLE(f.face)) return fail("a bitmap-only font cannot scale with the window");
    if (FT_Select_Charmap(f.face, FT_ENCODING_UNICODE) != 0)
        return fail("the font has no Unicode character map");
    // Glyph outlines are read lazily: render one now, so a truncated file fails here.
    const FT_UInt probe = FT_Get_Char_Index(f.face, 'a');
    if (!f.setSize(16.0f) || FT_Load_Glyph(f.face, probe, FT_LOAD_RENDER) != 0)
        return fail("the font is damaged: FreeType cannot render its glyphs");
    return font;
}

std::shared_ptr<const Font> Font::fallback(content::Diagnostics& diagnostics) {
    static const std::shared_ptr<const Font> font = [] {
        content::Diagnostics first;  // the error is given to every caller below, not once
        return load(kFallbackFontPath, first);
    }();
    if (!font) {
        diagnostics.error(kFallbackFontPath, "",
                          "the fallback font is missing (install fonts-dejavu-core); text is "
                          "not drawn");
    }
    return font;
}

std::uint32_t Font::glyphIndex(char32_t codepoint) const {
    const std::lock_guard lock(impl_->mutex);
    return FT_Get_Char_Index(impl_->face, codepoint);
}

LineMetrics Font::lineMetrics(float pixelSize) const {
    const std::lock_guard lock(impl_->mutex);
    if (!impl_->setSize(pixelSize)) return {};
    const FT_Size_Metrics& m = impl_->face->size->metrics;
    return {float(m.ascender) / 64.0f, -float(m.descender) / 64.0f, float(m.height) / 64.0f};
}

float Font::kerning(std::uint32_t left, std::uint32_t right, float pixelSize) const {
    const std::lock_guard lock(impl_->mutex);
    if (!FT_HAS_KERNING(impl_->face) || !impl_->setSize(pixelSize)) return 0.0f;
    FT_Vector delta{};
    if (FT_Get_Kerning(impl_->face, left, right, FT_KERNING_DEFAULT, &delta) != 0) return 0.0f;
    return float(delta.x) / 64.0f;
}

float Font::advance(std::uint32_t glyph, float pixelSize) const {
    const std::lock_guard lock(impl_->mutex);
    const auto key = std::pair{glyph, static_cast<FT_F26Dot6>(pixelSize * 64.0f + 0.5f)};
    if (auto it = impl_->advances.find(key); it != impl_->advances.end()) return it->second;
    float advance = 0.0f;
    if (impl_->setSize(pixelSize) &&
        FT_Load_Glyph(impl_->face, glyph, FT_LOAD_DEFAULT | FT_LOAD_TARGET_LIGHT) == 0) {
        advance = float(impl_->face->glyph->advance.x) / 64.0f;
    }
    impl_->advances.emplace(key, advance);
    return advance;
}

GlyphBitmap Font::rasterize(std::uint32_t glyph, float pixelSize) const {
    const std::lock_guard lock(impl_->mutex);
    GlyphBitmap out;
    // Light hinting: snapped to the pixel grid vertically only, so stems stay crisp at every
    // size without distorting the glyphs' widths.
    if (!impl_->setSize(pixelSize) ||
        FT_Load_Glyph(impl_->face, glyph, FT_LOAD_RENDER | FT_LOAD_TARGET_LIGHT) != 0) {
        return out;
    }
    const FT_GlyphSlot slot = impl_->face->glyph;
    const FT_Bitmap& bitmap = slot->bitmap;
    out.advance = float(slot->advance.x) / 64.0f;
    if (bitmap.pixel_mode != FT_PIXEL_MODE_GRAY) return out;  // a space, or nothing to draw
    out.width = bitmap.width;
    out.height = bitmap.rows;
    out.left = slot->bitmap_left;
    out.top = slot->bitmap_top;
    out.coverage.resize(std::size_t(out.width) * out.height);
    for (std::uint32_t y = 0; y < out.height; ++y) {
        const unsigned char* row =
            bitmap.pitch >= 0 ? bitmap.buffer + std::ptrdiff_t(y) * bitmap.pitch
                              : bitmap.buffer + std::ptrdiff_t(out.height - 1 - y) * -bitmap.pitch;
        std::copy_n(row, out.width, out.coverage.begin() + std::ptrdiff_t(y * out.width));
    }
    return out;
}

}  // namespace candela::gameui
