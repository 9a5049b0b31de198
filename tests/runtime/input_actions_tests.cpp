// InputActions (issue 47): named buttons and axes over keys, mouse and gamepad, rebound from a
// bindings file; a bad file names itself and changes nothing.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "candela/runtime/input_actions.h"

using namespace candela::runtime;

namespace {

InputActions defaults() {
    InputActions actions;
    actions.bindButton("jump", {"key:Space", "pad:A"});
    actions.bindButton("fire", {"mouse:left"});
    actions.bindAxis("move_x", {"key:A", "pad:DpadLeft"}, {"key:D", "pad:DpadRight"}, "pad:LeftX",
                     0.2f);
    return actions;
}

TEST(InputActions, ButtonsAndAxesReadEveryBoundDevice) {
    const InputActions actions = defaults();
    InputState input;
    input.setKey(Key::Space, true);
    EXPECT_TRUE(actions.down("jump", input));
    EXPECT_TRUE(actions.pressed("jump", input));
    input.beginFrame();
    EXPECT_FALSE(actions.pressed("jump", input));
    input.setKey(Key::Space, false);
    input.setButton(GamepadButton::A, true);
    EXPECT_TRUE(actions.pressed("jump", input));
    input.setButton(MouseButton::Left, true);
    EXPECT_TRUE(actions.down("fire", input));
    EXPECT_FALSE(actions.down("no such action", input));

    EXPECT_EQ(actions.axis("move_x", input), 0.0f);
    input.setKey(Key::D, true);
    EXPECT_EQ(actions.axis("move_x", input), 1.0f);
    input.setKey(Key::A, true);
    EXPECT_EQ(actions.axis("move_x", input), 0.0f) << "both keys cancel";
    input.setKey(Key::A, false);
    input.setKey(Key::D, false);
    // The stick: nothing inside the dead zone, then rescaled to start at 0.
    input.setAxis(GamepadAxis::LeftX, -0.15f);
    EXPECT_EQ(actions.axis("move_x", input), 0.0f);
    input.setAxis(GamepadAxis::LeftX, -0.6f);
    EXPECT_NEAR(actions.axis("move_x", input), -0.5f, 1e-6f);
    input.setAxis(GamepadAxis::LeftX, 1.0f);
    input.setKey(Key::D, true);
    EXPECT_EQ(actions.axis("move_x", input), 1.0f) << "clamped";
    EXPECT_EQ(actions.axis("no such axis", input), 0.0f);
}

TEST(InputActions, ABindingsFileRebindsWhatItNames) {
    InputActions actions = defaults();
    EXPECT_EQ(actions.parseBindings(R"({"buttons": {"jump": ["key:W", "pad:B"]},
        "axes": {"move_x": {"negative": ["key:Left"], "stick": "pad:RightX", "deadZone": 0.5}}})",
                                    "player.json"),
              "");
    InputState input;
    input.setKey(Key::Space, true);
    EXPECT_FALSE(actions.down("jump", input)) << "Space is no longer bound";
    input.setKey(Key::W, true);
    EXPECT_TRUE(actions.down("jump", input));
    input.setKey(Key::Left, true);
    EXPECT_EQ(actions.axis("move_x", input), -1.0f);
    input.setKey(Key::Left, false);
    input.setKey(Key::D, true);
    EXPECT_EQ(actions.axis("move_x", input), 1.0f) << "positive keys kept: the file left them";
    input.setKey(Key::D, false);
    input.setAxis(GamepadAxis::RightX, 0.75f);
    EXPECT_NEAR(actions.axis("move_x", input), 0.5f, 1e-6f);
}

TEST(InputActions, ABadBindingsFileNamesItselfAndChangesNothing) {
    const std::pair<const char*, const char*> cases[] = {
        {"not json", "not a bindings file"},
        {R"({"buttons": {"jupm": ["key:Space"]}})", "unknown action 'jupm' (jump, fire)"},
        {R"({"buttons": {"jump": ["key:Spcae"]}})", "'key:Spcae' is not a binding"},
        {R"({"buttons": {"jump": "key:Space"}})", "expected a list of bindings"},
        {R"({"axes": {"move_x": {"stick": "pad:Wheel"}}})", "move_x/stick"},
        {R"({"axes": {"move_x": {"deadZone": 1.5}}})", "deadZone: expected a number in [0, 1)"},
        {R"({"axes": {"move_y": {}}})", "unknown action 'move_y' (move_x)"},
        {R"({"keys": {}})", "unknown key 'keys'"},
        {R"({"buttons": {"jump": ["pad:B"]}, "axes": {"move_x": {"stick": "pad:Wheel"}}})",
         "Wheel"},
    };
    for (const auto& [text, words] : cases) {
        SCOPED_TRACE(text);
        InputActions actions = defaults();
        const std::string error = actions.parseBindings(text, "bad.json");
        EXPECT_EQ(error.rfind("bad.json: ", 0), 0u) << error;
        EXPECT_NE(error.find(words), std::string::npos) << error;
        InputState input;
        input.setKey(Key::Space, true);
        EXPECT_TRUE(actions.down("jump", input)) << "the defaults stand";
    }
    InputActions actions = defaults();
    const std::string missing = actions.loadBindings("/nonexistent/bindings.json");
    EXPECT_NE(missing.find("/nonexistent/bindings.json: cannot read bindings"), std::string::npos)
        << missing;
    EXPECT_THROW(actions.bindButton("x", {"key:Nope"}), std::invalid_argument);
}

}  // namespace
