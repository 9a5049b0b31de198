// UTF-8 a game shows: every valid form decodes, every malformed one is one U+FFFD.
#include <gtest/gtest.h>

#include "candela/gameui/utf8.h"

namespace candela::gameui {
namespace {

TEST(Utf8, DecodesOneToFourByteForms) {
    EXPECT_EQ(decodeUtf8("a\xC3\xA9\xE2\x82\xAC\xF0\x9F\x8E\xAE"),
              (std::u32string{U'a', U'\u00E9', U'\u20AC', U'\U0001F3AE'}));
    EXPECT_EQ(decodeUtf8(""), U"");
}

TEST(Utf8, EachMalformedSequenceBecomesOneReplacementCharacter) {
    const char32_t R = kReplacementCharacter;
    EXPECT_EQ(decodeUtf8("\x80x"), (std::u32string{R, U'x'}));       // stray continuation
    EXPECT_EQ(decodeUtf8("\xE2\x82x"), (std::u32string{R, U'x'}));   // truncated
    EXPECT_EQ(decodeUtf8("\xE2\x82"), (std::u32string{R}));          // truncated at the end
    EXPECT_EQ(decodeUtf8("\xC0\xAF"), (std::u32string{R}));          // overlong '/'
    EXPECT_EQ(decodeUtf8("\xED\xA0\x80"), (std::u32string{R}));      // a surrogate
    EXPECT_EQ(decodeUtf8("\xF4\x90\x80\x80"), (std::u32string{R}));  // past U+10FFFF
    EXPECT_EQ(decodeUtf8("\xFF"
                         "a"),
              (std::u32string{R, U'a'}));
}

}  // namespace
}  // namespace candela::gameui
