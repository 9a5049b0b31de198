#pragma once
// Named actions a game reads instead of keys: buttons ("jump") and axes ("move_x"), each bound
// to keys, mouse buttons, gamepad buttons and sticks. The game defines them with its default
// bindings; a bindings file it ships (and a player may edit) rebinds them:
//
//   InputActions actions;
//   actions.bindButton("jump", {"key:Space", "pad:A"});
//   actions.bindAxis("move_x", {"key:A", "key:Left", "pad:DpadLeft"},
//                    {"key:D", "key:Right", "pad:DpadRight"}, "pad:LeftX");
//   if (std::string error = actions.loadBindings("bindings.json"); !error.empty()) warn(error);
//   if (actions.pressed("jump", frame.keys())) jump();
//   float x = actions.axis("move_x", frame.keys());          // -1..1
//
// Bindings file (JSON): {"buttons": {"jump": ["key:Space", "pad:B"]},
//                        "axes": {"move_x": {"negative": [...], "positive": [...],
//                                            "stick": "pad:LeftX", "deadZone": 0.25}}}
// Only the actions the file names change; each it names replaces all of its bindings.
// Spellings: "key:<keyName>", "mouse:left|right|middle", "pad:<gamepadButtonName>" and, for
// sticks, "pad:<gamepadAxisName>".
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "candela/runtime/input_state.h"

namespace candela::runtime {

struct InputBinding {
    enum class Device : std::uint8_t { Key, Mouse, Pad };
    Device device = Device::Key;
    std::uint8_t index = 0;  // a Key, MouseButton or GamepadButton

    bool down(const InputState& input) const;
    bool pressed(const InputState& input) const;
};

class InputActions {
public:
    // Default bindings, by their spellings; a misspelt one throws std::invalid_argument (the
    // game's own code is wrong, not a player's file).
    void bindButton(std::string name, std::vector<std::string_view> bindings);
    void bindAxis(std::string name, std::vector<std::string_view> negative,
                  std::vector<std::string_view> positive, std::string_view stick = {},
                  float deadZone = 0.2f);

    // Rebinds from a bindings file. On any problem (unreadable, not JSON, an action the game
    // does not define, a binding misspelt, a dead zone outside [0, 1)) nothing changes and the
    // message names the file and the problem; empty on success.
    std::string loadBindings(const std::filesystem::path& path);
    std::string parseBindings(std::string_view json, const std::string& source);

    // An undefined name reads as never down and an axis at rest.
    bool down(std::string_view button, const InputState& input) const;
    bool pressed(std::string_view button, const InputState& input) const;
    // The keys' and buttons' -1 / +1 and the stick past its dead zone (rescaled to start at
    // 0), summed and clamped to [-1, 1].
    float axis(std::string_view axis, const InputState& input) const;

private:
    struct Button {
        std::string name;
        std::vector<InputBinding> bindings;
    };
    struct Axis {
        std::string name;
        std::vector<InputBinding> negative, positive;
        std::optional<GamepadAxis> stick;
        float deadZone = 0.2f;
    };
    const Button* findButton(std::string_view name) const;
    const Axis* findAxis(std::string_view name) const;

    std::vector<Button> buttons_;
    std::vector<Axis> axes_;
};

// "key:W" -> the binding; nullopt when misspelt.
std::optional<InputBinding> parseInputBinding(std::string_view spelling);

}  // namespace candela::runtime
