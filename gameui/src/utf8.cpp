#include "candela/gameui/utf8.h"

namespace candela::gameui {

std::u32string decodeUtf8(std::string_view text) {
    std::u32string out;
    out.reserve(text.size());
    std::size_t i = 0;
    while (i < text.size()) {
        const auto lead = static_cast<unsigned char>(text[i]);
        int length = 0;
        char32_t code = 0, minimum = 0;
        if (lead < 0x80) {
            out.push_back(lead);
            ++i;
            continue;
        } else if ((lead & 0xE0) == 0xC0) {
            length = 2, code = lead & 0x1F, minimum = 0x80;
        } else if ((lead & 0xF0) == 0xE0) {
            length = 3, code = lead & 0x0F, minimum = 0x800;
        } else if ((lead & 0xF8) == 0xF0) {
            length = 4, code = lead & 0x07, minimum = 0x10000;
        } else {
            out.push_back(kReplacementCharacter);  // a continuation byte or 0xF8..0xFF
            ++i;
            continue;
        }
        int read = 1;
        for (; read < length && i + read < text.size(); ++read) {
            const auto next = static_cast<unsigned char>(text[i + read]);
            if ((next & 0xC0) != 0x80) break;
            code = (code << 6) | (next & 0x3F);
        }
        i += read;
        const bool whole = read == length;
        const bool valid =
            whole && code >= minimum && code <= 0x10FFFF && !(code >= 0xD800 && code <= 0xDFFF);
        out.push_back(valid ? code : kReplacementCharacter);
    }
    return out;
}

}  // namespace candela::gameui
