// Recorded input: what a script means frame by frame, and scripts that are wrong must say
// where (file:line) and why, never crash.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <utility>

#include "candela/runtime/input_script.h"

using namespace candela::runtime;

namespace {

InputScript parseOk(const std::string& text) {
    std::string error;
    std::optional<InputScript> script = InputScript::parse(text, "test.input", error);
    EXPECT_TRUE(script.has_value()) << error;
    return script ? *script : InputScript{};
}

std::string parseError(const std::string& text) {
    std::string error;
    std::optional<InputScript> script = InputScript::parse(text, "bad.input", error);
    EXPECT_FALSE(script.has_value()) << "accepted: " << text;
    return error;
}

}  // namespace

TEST(InputScript, KeysGoDownAndUpOnTheirFrames) {
    InputScript script = parseOk("# move right\n2 down d\n4 up D   # release\n");
    InputState state;
    std::vector<bool> down, pressed;
    for (uint32_t frame = 0; frame < 6; ++frame) {
        state.beginFrame();
        script.apply(frame, state);
        down.push_back(state.down(Key::D));
        pressed.push_back(state.pressed(Key::D));
    }
    EXPECT_EQ(down, (std::vector<bool>{false, false, true, true, false, false}));
    EXPECT_EQ(pressed, (std::vector<bool>{false, false, true, false, false, false}));
}

// Issue 44: a script saved with a UTF-8 byte order mark reads as the same script.
TEST(InputScript, ByteOrderMarkIsNotPartOfTheFirstFrameNumber) {
    InputScript withMark = parseOk(
        "\xEF\xBB\xBF"
        "0 down d\n2 up d\n");
    InputState state;
    state.beginFrame();
    withMark.apply(0, state);
    EXPECT_TRUE(state.down(Key::D));
    // Only at the start: a mark anywhere else is still an error.
    EXPECT_NE(parseError("0 down d\n\xEF\xBB\xBF"
                         "2 up d\n")
                  .find("bad.input:2"),
              std::string::npos);
}

TEST(InputScript, TapHoldMouseButtonAndQuit) {
    InputScript script =
        parseOk("1 tap R\n0 hold LeftShift 3\n1 mouse 4.5 -2\n2 button down left\n5 quit\n");
    InputState state;
    state.beginFrame();
    script.apply(0, state);
    EXPECT_TRUE(state.down(Key::LeftShift));
    EXPECT_FALSE(state.down(Key::R));
    state.beginFrame();
    script.apply(1, state);
    EXPECT_TRUE(state.pressed(Key::R));
    EXPECT_FLOAT_EQ(state.mouseDeltaX, 4.5f);
    EXPECT_FLOAT_EQ(state.mouseDeltaY, -2.0f);
    state.beginFrame();
    script.apply(2, state);
    EXPECT_FALSE(state.down(Key::R));
    EXPECT_FLOAT_EQ(state.mouseDeltaX, 0.0f);
    EXPECT_TRUE(state.pressed(MouseButton::Left));
    state.beginFrame();
    script.apply(3, state);
    EXPECT_FALSE(state.down(Key::LeftShift));
    EXPECT_FALSE(state.closeRequested);
    state.beginFrame();
    script.apply(5, state);
    EXPECT_TRUE(state.closeRequested);
}

TEST(InputScript, BadScriptsNameTheLineAndTheProblem) {
    EXPECT_EQ(parseError("0 down W\n\n3 down Q2\n").rfind("bad.input:3: unknown key 'Q2'", 0), 0u);
    EXPECT_NE(parseError("x down W").find("bad.input:1: expected a frame number"),
              std::string::npos);
    EXPECT_NE(parseError("-1 down W").find("expected a frame number"), std::string::npos);
    EXPECT_NE(parseError("4").find("bad.input:1: frame 4 has no action"), std::string::npos);
    EXPECT_NE(parseError("1 jump W").find("unknown action 'jump'"), std::string::npos);
    EXPECT_NE(parseError("1 down").find("'down' takes one key"), std::string::npos);
    EXPECT_NE(parseError("1 down W S").find("'down' takes one key"), std::string::npos);
    EXPECT_NE(parseError("1 hold W 0").find("positive frame count"), std::string::npos);
    EXPECT_NE(parseError("1 mouse 1 nan").find("two finite numbers"), std::string::npos);
    EXPECT_NE(parseError("1 mouse 1").find("'mouse' takes dx and dy"), std::string::npos);
    EXPECT_NE(parseError("1 button down thumb").find("unknown mouse button 'thumb'"),
              std::string::npos);
    EXPECT_NE(parseError("4294967295 tap W").find("ends past the last frame"), std::string::npos);
    EXPECT_NE(parseError("99999999999 down W").find("expected a frame number"), std::string::npos);
}

TEST(InputScript, MissingFileIsAClearError) {
    std::string error;
    EXPECT_FALSE(InputScript::load("/nonexistent/dir/x.input", error).has_value());
    EXPECT_EQ(error, "/nonexistent/dir/x.input: cannot open input script: no such file");
}

// Issue 22: /dev/zero used to end in std::bad_alloc, a directory ran as an empty script, and
// a FIFO would hang. Each is refused with the file named, before anything is read.
TEST(InputScript, SpecialFilesAndHugeFilesAreRefusedBeforeReading) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("candela-input-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::filesystem::path fifo = dir / "fifo.input";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const std::filesystem::path huge = dir / "huge.input";
    { std::ofstream(huge) << "0 down W\n"; }
    std::filesystem::resize_file(huge, InputScript::kMaxFileBytes + 1);  // sparse
    const std::pair<std::filesystem::path, std::string> cases[] = {
        {"/dev/zero", "not a regular file (a character device)"},
        {dir, "not a regular file (a directory)"},
        {fifo, "not a regular file (a FIFO)"},
        {huge, "over the limit of 16777216"}};
    for (const auto& [path, problem] : cases) {
        std::string error;
        EXPECT_FALSE(InputScript::load(path, error).has_value()) << path;
        EXPECT_NE(error.find(path.string() + ": cannot open input script: "), std::string::npos)
            << error;
        EXPECT_NE(error.find(problem), std::string::npos) << error;
    }
    std::filesystem::remove_all(dir);
}

TEST(InputScript, KeyNamesRoundTrip) {
    for (size_t i = 0; i < kKeyCount; ++i) {
        std::optional<Key> k = keyFromName(keyName(Key(i)));
        ASSERT_TRUE(k.has_value()) << keyName(Key(i));
        EXPECT_EQ(size_t(*k), i);
    }
}

// Issue 47: scripts replay a gamepad as they replay keys: buttons go down and up on their
// frames (pressed once), axes move and stay, and bad names or values name the line.
TEST(InputScript, GamepadButtonsAndAxesReplay) {
    const InputScript script = parseOk(
        "0 pad down A\n"
        "0 stick LeftX -0.75\n"
        "2 pad up a\n"
        "2 stick lefttrigger 1\n"
        "3 stick LeftX 0\n");
    InputState state;
    EXPECT_EQ(state.axis(GamepadAxis::LeftTrigger), -1.0f) << "a released trigger";
    script.apply(0, state);
    EXPECT_TRUE(state.down(GamepadButton::A));
    EXPECT_TRUE(state.pressed(GamepadButton::A));
    EXPECT_EQ(state.axis(GamepadAxis::LeftX), -0.75f);
    state.beginFrame();
    script.apply(1, state);
    EXPECT_TRUE(state.down(GamepadButton::A));
    EXPECT_FALSE(state.pressed(GamepadButton::A));
    EXPECT_EQ(state.axis(GamepadAxis::LeftX), -0.75f) << "an axis stays where it was moved";
    state.beginFrame();
    script.apply(2, state);
    EXPECT_FALSE(state.down(GamepadButton::A));
    EXPECT_EQ(state.axis(GamepadAxis::LeftTrigger), 1.0f);
    state.beginFrame();
    script.apply(3, state);
    EXPECT_EQ(state.axis(GamepadAxis::LeftX), 0.0f);

    EXPECT_NE(parseError("1 pad down Z").find("bad.input:1: unknown gamepad button 'Z'"),
              std::string::npos);
    EXPECT_NE(parseError("1 pad push A").find("'pad' needs down or up"), std::string::npos);
    EXPECT_NE(parseError("1 stick Wheel 0").find("unknown gamepad axis 'Wheel'"),
              std::string::npos);
    EXPECT_NE(parseError("1 stick LeftX 1.5").find("a value in [-1, 1]"), std::string::npos);
    EXPECT_NE(parseError("1 stick LeftX nan").find("a value in [-1, 1]"), std::string::npos);
    // Axis values a device reports out of range are clamped; a NaN reads as rest.
    state.setAxis(GamepadAxis::RightY, 7.0f);
    EXPECT_EQ(state.axis(GamepadAxis::RightY), 1.0f);
    state.setAxis(GamepadAxis::RightTrigger, std::numeric_limits<float>::quiet_NaN());
    EXPECT_EQ(state.axis(GamepadAxis::RightTrigger), -1.0f);
}

TEST(InputScript, GamepadNamesRoundTrip) {
    for (std::size_t i = 0; i < kGamepadButtonCount; ++i) {
        const auto button = GamepadButton(i);
        EXPECT_EQ(gamepadButtonFromName(gamepadButtonName(button)), button);
    }
    for (std::size_t i = 0; i < kGamepadAxisCount; ++i) {
        const auto axis = GamepadAxis(i);
        EXPECT_EQ(gamepadAxisFromName(gamepadAxisName(axis)), axis);
    }
    EXPECT_FALSE(gamepadButtonFromName("Select").has_value());
}
