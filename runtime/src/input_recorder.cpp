#include "candela/runtime/input_recorder.h"

#include <cstdio>

#include "candela/content/atomic_file_write.h"

namespace candela::runtime {
namespace {

// Sticks and triggers in thousandths: finer than a pad reports, and a replay's value then
// reads back exactly as recorded.
float quantized(float value) {
    return static_cast<float>(static_cast<int>(value * 1000.0f + (value < 0 ? -0.5f : 0.5f))) /
           1000.0f;
}

}  // namespace

void InputRecorder::record(std::uint32_t frame, const InputState& state) {
    const std::string at = std::to_string(frame) + " ";
    const auto line = [&](const std::string& rest) { text_ += at + rest + "\n"; };
    for (std::size_t i = 0; i < kKeyCount; ++i) {
        const std::string name(keyName(Key(i)));
        if (state.keysDown[i] != last_.keysDown[i]) {
            line((state.keysDown[i] ? "down " : "up ") + name);
        } else if (state.keysPressed[i] && !state.keysDown[i]) {
            line("tap " + name);  // down and up again between two frames
        }
    }
    for (std::size_t i = 0; i < kMouseButtonCount; ++i) {
        if (state.buttonsDown[i] != last_.buttonsDown[i]) {
            line(std::string("button ") + (state.buttonsDown[i] ? "down " : "up ") +
                 std::string(mouseButtonName(MouseButton(i))));
        }
    }
    if (state.mouseDeltaX != 0.0f || state.mouseDeltaY != 0.0f) {
        char move[64];
        std::snprintf(move, sizeof move, "mouse %g %g", state.mouseDeltaX, state.mouseDeltaY);
        line(move);
    }
    for (std::size_t i = 0; i < kGamepadButtonCount; ++i) {
        if (state.padDown[i] != last_.padDown[i]) {
            line(std::string("pad ") + (state.padDown[i] ? "down " : "up ") +
                 std::string(gamepadButtonName(GamepadButton(i))));
        }
    }
    for (std::size_t i = 0; i < kGamepadAxisCount; ++i) {
        const float value = quantized(state.padAxes[i]);
        if (value != quantized(last_.padAxes[i])) {
            char stick[64];
            std::snprintf(stick, sizeof stick, "stick %s %g",
                          std::string(gamepadAxisName(GamepadAxis(i))).c_str(), value);
            line(stick);
        }
    }
    last_ = state;
}

void InputRecorder::recordQuit(std::uint32_t frame) {
    text_ += std::to_string(frame) + " quit\n";
}

std::string InputRecorder::write(const std::filesystem::path& path) const {
    return content::writeFileAtomically(path, text_);
}

}  // namespace candela::runtime
