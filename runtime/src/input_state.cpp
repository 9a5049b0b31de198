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

constexpr std::array<std::string_view, kGamepadButtonCount> kPadButtonNames = {
    "A",     "B",         "X",          "Y",      "LeftBumper", "RightBumper", "Back",    "Start",
    "Guide", "LeftThumb", "RightThumb", "DpadUp", "DpadRight",  "DpadDown",    "DpadLeft"};

constexpr std::array<std::string_view, kGamepadAxisCount> kPadAxisNames = {
    "LeftX", "LeftY", "RightX", "RightY", "LeftTrigger", "RightTrigger"};

bool equalsIgnoringCase(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) ==
                      std::tolower(static_cast<unsigned char>(y));
           });
}

template <class E, std::size_t N>
std::optional<E> fromName(const std::array<std::string_view, N>& names, std::string_view name) {
    for (std::size_t i = 0; i < N; ++i) {
        if (equalsIgnoringCase(names[i], name)) return E(i);
    }
    return std::nullopt;
}

}  // namespace

std::string_view keyName(Key key) {
    return std::size_t(key) < kKeyCount ? kKeyNames[std::size_t(key)] : "?";
}

std::optional<Key> keyFromName(std::string_view name) {
    return fromName<Key>(kKeyNames, name);
}

std::string_view mouseButtonName(MouseButton button) {
    return std::size_t(button) < kMouseButtonCount ? kButtonNames[std::size_t(button)] : "?";
}

std::optional<MouseButton> mouseButtonFromName(std::string_view name) {
    return fromName<MouseButton>(kButtonNames, name);
}

std::string_view gamepadButtonName(GamepadButton button) {
    return std::size_t(button) < kGamepadButtonCount ? kPadButtonNames[std::size_t(button)] : "?";
}

std::optional<GamepadButton> gamepadButtonFromName(std::string_view name) {
    return fromName<GamepadButton>(kPadButtonNames, name);
}

std::string_view gamepadAxisName(GamepadAxis axis) {
    return std::size_t(axis) < kGamepadAxisCount ? kPadAxisNames[std::size_t(axis)] : "?";
}

std::optional<GamepadAxis> gamepadAxisFromName(std::string_view name) {
    return fromName<GamepadAxis>(kPadAxisNames, name);
}

}  // namespace candela::runtime
