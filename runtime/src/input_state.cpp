#include <algorithm>
#include <cctype>
#include <string>

#include "candela/runtime/input_state.h"

namespace candela::runtime {

namespace {

constexpr std::array<std::string_view, kKeyCount> kKeyNames = {
    "A",       "B",        "C",     "D",         "E",          "F",           "G",
    "H",       "I",        "J",     "K",         "L",          "M",           "N",
    "O",       "P",        "Q",     "R",         "S",          "T",           "U",
    "V",       "W",        "X",     "Y",         "Z",          "0",           "1",
    "2",       "3",        "4",     "5",         "6",          "7",           "8",
    "9",       "Space",    "Enter", "Escape",    "Tab",        "Backspace",   "Left",
    "Right",   "Up",       "Down",  "LeftShift", "RightShift", "LeftControl", "RightControl",
    "LeftAlt", "RightAlt", "F1",    "F2",        "F3",         "F4"};

constexpr std::array<std::string_view, kMouseButtonCount> kButtonNames = {"left", "right",
                                                                          "middle"};

bool equalsIgnoringCase(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) ==
                      std::tolower(static_cast<unsigned char>(y));
           });
}

}  // namespace

std::string_view keyName(Key key) {
    return std::size_t(key) < kKeyCount ? kKeyNames[std::size_t(key)] : "?";
}

std::optional<Key> keyFromName(std::string_view name) {
    for (std::size_t i = 0; i < kKeyCount; ++i) {
        if (equalsIgnoringCase(kKeyNames[i], name)) return Key(i);
    }
    return std::nullopt;
}

std::string_view mouseButtonName(MouseButton button) {
    return std::size_t(button) < kMouseButtonCount ? kButtonNames[std::size_t(button)] : "?";
}

std::optional<MouseButton> mouseButtonFromName(std::string_view name) {
    for (std::size_t i = 0; i < kMouseButtonCount; ++i) {
        if (equalsIgnoringCase(kButtonNames[i], name)) return MouseButton(i);
    }
    return std::nullopt;
}

}  // namespace candela::runtime
