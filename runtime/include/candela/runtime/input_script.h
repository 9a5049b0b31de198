#pragma once
// Recorded input for headless runs: a text file of frame-stamped events, replayed into an
// InputState so a run sees the same input every time.
//
//   # comment
//   <frame> down <key>            key goes down at the start of <frame>
//   <frame> up <key>
//   <frame> tap <key>             down at <frame>, up at <frame>+1
//   <frame> hold <key> <frames>   down at <frame>, up at <frame>+<frames>
//   <frame> mouse <dx> <dy>       mouse moves by (dx, dy) pixels during <frame>
//   <frame> button down|up left|right|middle
//   <frame> pad down|up <button>  a gamepad button (gamepadButtonName: A, B, X, Y, DpadUp, ...)
//   <frame> stick <axis> <value>  a gamepad axis (LeftX, LeftY, ..., RightTrigger) moves to
//                                 <value> in [-1, 1] and stays there
//   <frame> quit                  the run ends before <frame> renders
//
// Keys are named as keyName() spells them (case-insensitive). Frames count from 0.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "candela/runtime/input_state.h"

namespace candela::runtime {

struct InputEvent {
    enum class Type : std::uint8_t {
        KeyDown,
        KeyUp,
        MouseMove,
        ButtonDown,
        ButtonUp,
        PadDown,
        PadUp,
        PadAxis,
        Quit
    };
    std::uint32_t frame = 0;
    Type type = Type::KeyDown;
    Key key = Key::A;
    MouseButton button = MouseButton::Left;
    GamepadButton padButton = GamepadButton::A;
    GamepadAxis padAxis = GamepadAxis::LeftX;
    float dx = 0.0f, dy = 0.0f;  // a mouse move; dx: a pad axis's value
};

class InputScript {
public:
    // Parses script text; `source` names it in errors ("file:line: problem").
    static std::optional<InputScript> parse(std::string_view text, const std::string& source,
                                            std::string& error);
    // Scripts are text a person writes: larger files (and FIFOs, devices such as /dev/zero,
    // directories) are refused with an error naming the file, before anything is read.
    static constexpr std::uint64_t kMaxFileBytes = 16ull * 1024 * 1024;
    static std::optional<InputScript> load(const std::filesystem::path& path, std::string& error);

    // Applies the events of `frame` to `state` (after state.beginFrame()).
    void apply(std::uint32_t frame, InputState& state) const;
    const std::vector<InputEvent>& events() const { return events_; }  // sorted by frame

private:
    std::vector<InputEvent> events_;
};

}  // namespace candela::runtime
