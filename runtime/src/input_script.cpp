#include "candela/runtime/input_script.h"

#include "candela/content/file_bytes.h"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <limits>
#include <sstream>

namespace candela::runtime {

namespace {

bool parseFrame(const std::string& text, std::uint32_t& value) {
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, value);
    return ec == std::errc() && ptr == end;
}

bool parseFloat(const std::string& text, float& value) {
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, value);
    return ec == std::errc() && ptr == end && value == value && value - value == 0.0f;
}

}  // namespace

std::optional<InputScript> InputScript::parse(std::string_view text, const std::string& source,
                                              std::string& error) {
    InputScript script;
    // A UTF-8 byte order mark (editors on Windows write one) is not part of the first line:
    // it was read as part of its frame number ("got '\ufeff0'").
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    std::istringstream lines{std::string(text)};
    std::string line;
    std::uint32_t lineNumber = 0;
    auto fail = [&](const std::string& problem) {
        error = source + ":" + std::to_string(lineNumber) + ": " + problem;
        return std::nullopt;
    };
    while (std::getline(lines, line)) {
        ++lineNumber;
        if (size_t hash = line.find('#'); hash != std::string::npos) line.resize(hash);
        std::istringstream words(line);
        std::vector<std::string> w;
        for (std::string word; words >> word;)
            w.push_back(word);
        if (w.empty()) continue;
        InputEvent event;
        if (!parseFrame(w[0], event.frame)) {
            return fail("expected a frame number (0 or more) first, got '" + w[0] + "'");
        }
        if (w.size() < 2) return fail("frame " + w[0] + " has no action");
        const std::string& action = w[1];
        auto expectWords = [&](size_t n, const char* usage) -> bool {
            if (w.size() == n) return true;
            error = source + ":" + std::to_string(lineNumber) + ": '" + action + "' takes " + usage;
            return false;
        };
        auto key = [&](const std::string& name) -> std::optional<Key> {
            std::optional<Key> k = keyFromName(name);
            if (!k) {
                error = source + ":" + std::to_string(lineNumber) + ": unknown key '" + name +
                        "' (keys: A-Z, 0-9, Space, Enter, Escape, Tab, Backspace, arrows "
                        "Left/Right/Up/Down, LeftShift, RightShift, LeftControl, RightControl, "
                        "LeftAlt, RightAlt, F1-F4)";
            }
            return k;
        };
        if (action == "down" || action == "up") {
            if (!expectWords(3, "one key")) return std::nullopt;
            std::optional<Key> k = key(w[2]);
            if (!k) return std::nullopt;
            event.type = action == "down" ? InputEvent::Type::KeyDown : InputEvent::Type::KeyUp;
            event.key = *k;
            script.events_.push_back(event);
        } else if (action == "tap" || action == "hold") {
            if (!expectWords(action == "tap" ? 3 : 4,
                             action == "tap" ? "one key" : "a key and a frame count")) {
                return std::nullopt;
            }
            std::optional<Key> k = key(w[2]);
            if (!k) return std::nullopt;
            std::uint32_t length = 1;
            if (action == "hold" && (!parseFrame(w[3], length) || length == 0)) {
                return fail("'hold' needs a positive frame count, got '" + w[3] + "'");
            }
            if (event.frame > std::numeric_limits<std::uint32_t>::max() - length) {
                return fail("'" + action + "' ends past the last frame number");
            }
            event.type = InputEvent::Type::KeyDown;
            event.key = *k;
            script.events_.push_back(event);
            event.type = InputEvent::Type::KeyUp;
            event.frame += length;
            script.events_.push_back(event);
        } else if (action == "mouse") {
            if (!expectWords(4, "dx and dy in pixels")) return std::nullopt;
            if (!parseFloat(w[2], event.dx) || !parseFloat(w[3], event.dy)) {
                return fail("'mouse' needs two finite numbers, got '" + w[2] + "' '" + w[3] + "'");
            }
            event.type = InputEvent::Type::MouseMove;
            script.events_.push_back(event);
        } else if (action == "button") {
            if (!expectWords(4, "down|up and left|right|middle")) return std::nullopt;
            if (w[2] != "down" && w[2] != "up") {
                return fail("'button' needs down or up, got '" + w[2] + "'");
            }
            std::optional<MouseButton> b = mouseButtonFromName(w[3]);
            if (!b) return fail("unknown mouse button '" + w[3] + "' (left, right, middle)");
            event.type = w[2] == "down" ? InputEvent::Type::ButtonDown : InputEvent::Type::ButtonUp;
            event.button = *b;
            script.events_.push_back(event);
        } else if (action == "pad") {
            if (!expectWords(4, "down|up and a gamepad button")) return std::nullopt;
            if (w[2] != "down" && w[2] != "up") {
                return fail("'pad' needs down or up, got '" + w[2] + "'");
            }
            std::optional<GamepadButton> b = gamepadButtonFromName(w[3]);
            if (!b) {
                return fail("unknown gamepad button '" + w[3] +
                            "' (A, B, X, Y, LeftBumper, RightBumper, Back, Start, Guide, "
                            "LeftThumb, RightThumb, DpadUp, DpadRight, DpadDown, DpadLeft)");
            }
            event.type = w[2] == "down" ? InputEvent::Type::PadDown : InputEvent::Type::PadUp;
            event.padButton = *b;
            script.events_.push_back(event);
        } else if (action == "stick") {
            if (!expectWords(4, "a gamepad axis and a value in [-1, 1]")) return std::nullopt;
            std::optional<GamepadAxis> a = gamepadAxisFromName(w[2]);
            if (!a) {
                return fail("unknown gamepad axis '" + w[2] +
                            "' (LeftX, LeftY, RightX, RightY, LeftTrigger, RightTrigger)");
            }
            if (!parseFloat(w[3], event.dx) || event.dx < -1.0f || event.dx > 1.0f) {
                return fail("'stick' needs a value in [-1, 1], got '" + w[3] + "'");
            }
            event.type = InputEvent::Type::PadAxis;
            event.padAxis = *a;
            script.events_.push_back(event);
        } else if (action == "quit") {
            if (!expectWords(2, "nothing")) return std::nullopt;
            event.type = InputEvent::Type::Quit;
            script.events_.push_back(event);
        } else {
            return fail("unknown action '" + action +
                        "' (down, up, tap, hold, mouse, button, pad, stick, quit)");
        }
    }
    // Stable: events of one frame apply in file order (a down then an up is a tap).
    std::stable_sort(script.events_.begin(), script.events_.end(),
                     [](const InputEvent& a, const InputEvent& b) { return a.frame < b.frame; });
    return script;
}

std::optional<InputScript> InputScript::load(const std::filesystem::path& path,
                                             std::string& error) {
    content::FileBytes file = content::readFileBytes(path, kMaxFileBytes);
    if (!file.error.empty()) {
        error = path.string() + ": cannot open input script: " + file.error;
        return std::nullopt;
    }
    const std::string_view text(reinterpret_cast<const char*>(file.bytes.data()),
                                file.bytes.size());
    return parse(text, path.string(), error);
}

void InputScript::apply(std::uint32_t frame, InputState& state) const {
    auto first = std::lower_bound(events_.begin(), events_.end(), frame,
                                  [](const InputEvent& e, std::uint32_t f) { return e.frame < f; });
    for (auto it = first; it != events_.end() && it->frame == frame; ++it) {
        switch (it->type) {
            case InputEvent::Type::KeyDown:
                state.setKey(it->key, true);
                break;
            case InputEvent::Type::KeyUp:
                state.setKey(it->key, false);
                break;
            case InputEvent::Type::MouseMove:
                state.mouseDeltaX += it->dx;
                state.mouseDeltaY += it->dy;
                state.mouseX += it->dx;
                state.mouseY += it->dy;
                break;
            case InputEvent::Type::ButtonDown:
                state.setButton(it->button, true);
                break;
            case InputEvent::Type::ButtonUp:
                state.setButton(it->button, false);
                break;
            case InputEvent::Type::PadDown:
                state.setButton(it->padButton, true);
                break;
            case InputEvent::Type::PadUp:
                state.setButton(it->padButton, false);
                break;
            case InputEvent::Type::PadAxis:
                state.setAxis(it->padAxis, it->dx);
                break;
            case InputEvent::Type::Quit:
                state.closeRequested = true;
                break;
        }
    }
}

}  // namespace candela::runtime
