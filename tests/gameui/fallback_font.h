#pragma once
// The fallback font (DejaVu Sans), loaded once for the gameui tests that lay out text.
#include "candela/gameui/font.h"

namespace candela::gameui::test {

inline const Font& fallbackFont() {
    static const std::shared_ptr<const Font> font = [] {
        content::Diagnostics diagnostics;
        return Font::fallback(diagnostics);
    }();
    return *font;
}

}  // namespace candela::gameui::test
