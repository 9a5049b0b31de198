#pragma once
// UTF-8 to code points for text a game shows. Malformed input (a stray continuation byte, a
// truncated sequence, an overlong encoding, a surrogate, past U+10FFFF) becomes U+FFFD, one per
// bad sequence, so bad text shows where it is bad and never stops the rest.
#include <string>
#include <string_view>

namespace candela::gameui {

inline constexpr char32_t kReplacementCharacter = 0xFFFD;

std::u32string decodeUtf8(std::string_view text);

}  // namespace candela::gameui
