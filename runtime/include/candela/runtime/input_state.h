#pragma once
// Keyboard, mouse and gamepad as plain data, the same whether a window (GLFW) or a recorded
// input script fills it; game systems read only this.
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace candela::runtime {

enum class Key : std::uint8_t {
    A,
    B,
    C,
    D,
    E,
    F,
    G,
    H,
    I,
    J,
    K,
    L,
    M,
    N,
    O,
    P,
    Q,
    R,
    S,
    T,
    U,
    V,
    W,
    X,
    Y,
    Z,
    Num0,
    Num1,
    Num2,
    Num3,
    Num4,
    Num5,
    Num6,
    Num7,
    Num8,
    Num9,
    Space,
    Enter,
    Escape,
    Tab,
    Backspace,
    Left,
    Right,
    Up,
    Down,
    LeftShift,
    RightShift,
    LeftControl,
    RightControl,
    LeftAlt,
    RightAlt,
    F1,
    F2,
    F3,
    F4,
    Count
};
inline constexpr std::size_t kKeyCount = std::size_t(Key::Count);

enum class MouseButton : std::uint8_t { Left, Right, Middle, Count };
inline constexpr std::size_t kMouseButtonCount = std::size_t(MouseButton::Count);

// The first gamepad's buttons and axes, in the layout of GLFW's gamepad API (an Xbox-style pad
// through SDL's mapping database, whatever the device): GLFW_GAMEPAD_BUTTON_* and _AXIS_*.
enum class GamepadButton : std::uint8_t {
    A,
    B,
    X,
    Y,
    LeftBumper,
    RightBumper,
    Back,
    Start,
    Guide,
    LeftThumb,
    RightThumb,
    DpadUp,
    DpadRight,
    DpadDown,
    DpadLeft,
    Count
};
inline constexpr std::size_t kGamepadButtonCount = std::size_t(GamepadButton::Count);
// Sticks in [-1, 1], +Y down (as GLFW reports them); triggers from -1 (released) to 1.
enum class GamepadAxis : std::uint8_t {
    LeftX,
    LeftY,
    RightX,
    RightY,
    LeftTrigger,
    RightTrigger,
    Count
};
inline constexpr std::size_t kGamepadAxisCount = std::size_t(GamepadAxis::Count);

// Names as input scripts spell them: "A".."Z", "0".."9", "Space", "LeftShift", "F1", ...
std::string_view keyName(Key key);
std::optional<Key> keyFromName(std::string_view name);  // case-insensitive
std::string_view mouseButtonName(MouseButton button);
std::optional<MouseButton> mouseButtonFromName(std::string_view name);  // case-insensitive
// "A", "B", "X", "Y", "LeftBumper", ..., "DpadLeft"; "LeftX", ..., "RightTrigger".
std::string_view gamepadButtonName(GamepadButton button);
std::optional<GamepadButton> gamepadButtonFromName(std::string_view name);  // case-insensitive
std::string_view gamepadAxisName(GamepadAxis axis);
std::optional<GamepadAxis> gamepadAxisFromName(std::string_view name);  // case-insensitive

struct InputState {
    std::array<bool, kKeyCount> keysDown{};
    std::array<bool, kKeyCount> keysPressed{};  // went down since the previous frame
    std::array<bool, kMouseButtonCount> buttonsDown{};
    std::array<bool, kMouseButtonCount> buttonsPressed{};
    float mouseX = 0.0f, mouseY = 0.0f;            // window pixels, origin top-left
    float mouseDeltaX = 0.0f, mouseDeltaY = 0.0f;  // movement since the previous frame
    std::array<bool, kGamepadButtonCount> padDown{};
    std::array<bool, kGamepadButtonCount> padPressed{};  // went down since the previous frame
    // Raw positions (no dead zone): sticks at rest, triggers released.
    std::array<float, kGamepadAxisCount> padAxes{0.0f, 0.0f, 0.0f, 0.0f, -1.0f, -1.0f};
    bool closeRequested = false;  // the window's close button, or `quit` in a script

    bool down(Key key) const { return keysDown[std::size_t(key)]; }
    bool pressed(Key key) const { return keysPressed[std::size_t(key)]; }
    bool down(MouseButton b) const { return buttonsDown[std::size_t(b)]; }
    bool pressed(MouseButton b) const { return buttonsPressed[std::size_t(b)]; }
    bool down(GamepadButton b) const { return padDown[std::size_t(b)]; }
    bool pressed(GamepadButton b) const { return padPressed[std::size_t(b)]; }
    float axis(GamepadAxis a) const { return padAxes[std::size_t(a)]; }

    // Starts a new frame: what was pressed or moved belongs to the previous one.
    void beginFrame() {
        keysPressed = {};
        buttonsPressed = {};
        padPressed = {};
        mouseDeltaX = mouseDeltaY = 0.0f;
    }
    void setKey(Key key, bool isDown) {
        std::size_t i = std::size_t(key);
        if (isDown && !keysDown[i]) keysPressed[i] = true;
        keysDown[i] = isDown;
    }
    void setButton(MouseButton button, bool isDown) {
        std::size_t i = std::size_t(button);
        if (isDown && !buttonsDown[i]) buttonsPressed[i] = true;
        buttonsDown[i] = isDown;
    }
    void setButton(GamepadButton button, bool isDown) {
        std::size_t i = std::size_t(button);
        if (isDown && !padDown[i]) padPressed[i] = true;
        padDown[i] = isDown;
    }
    // Clamped to [-1, 1]; a NaN reads as the axis at rest.
    void setAxis(GamepadAxis axis, float value) {
        const std::size_t i = std::size_t(axis);
        const float rest = i >= std::size_t(GamepadAxis::LeftTrigger) ? -1.0f : 0.0f;
        padAxes[i] = value == value ? (value < -1.0f ? -1.0f : value > 1.0f ? 1.0f : value) : rest;
    }
};

}  // namespace candela::runtime
