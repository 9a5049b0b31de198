// Issue 47: --record-input writes what the input did as a script that replays it: every key,
// mouse and gamepad change reads back from the script as it was, frame by frame.
#include <gtest/gtest.h>

#include <vector>

#include "candela/runtime/input_recorder.h"
#include "candela/runtime/input_script.h"

namespace candela::runtime {
namespace {

// Frames of live input, built as a window would deliver them.
std::vector<InputState> session() {
    std::vector<InputState> frames;
    InputState s;
    const auto next = [&](auto&& change) {
        s.beginFrame();
        change(s);
        frames.push_back(s);
    };
    next([](InputState&) {});
    next([](InputState& i) { i.setKey(Key::W, true); });
    next([](InputState& i) {
        i.setKey(Key::D, true);
        i.setButton(MouseButton::Left, true);
        i.mouseDeltaX = 12.0f;
        i.mouseDeltaY = -3.5f;
    });
    next([](InputState& i) {
        i.setKey(Key::W, false);
        i.setButton(GamepadButton::A, true);
        i.setAxis(GamepadAxis::LeftX, -0.75f);
        i.setAxis(GamepadAxis::RightTrigger, 0.5f);
    });
    next([](InputState& i) {
        i.setButton(MouseButton::Left, false);
        i.setButton(GamepadButton::A, false);
        i.setAxis(GamepadAxis::LeftX, 0.0f);
    });
    next([](InputState& i) { i.setKey(Key::D, false); });
    return frames;
}

TEST(InputRecorder, ARecordedSessionReplaysFrameByFrame) {
    const std::vector<InputState> live = session();
    InputRecorder recorder;
    for (std::uint32_t f = 0; f < live.size(); ++f)
        recorder.record(f, live[f]);
    recorder.recordQuit(std::uint32_t(live.size()));
    std::string error;
    const auto script = InputScript::parse(recorder.text(), "recorded.input", error);
    ASSERT_TRUE(script) << error << "\n" << recorder.text();
    InputState replayed;
    for (std::uint32_t f = 0; f < live.size(); ++f) {
        SCOPED_TRACE(f);
        replayed.beginFrame();
        script->apply(f, replayed);
        EXPECT_EQ(replayed.keysDown, live[f].keysDown);
        EXPECT_EQ(replayed.keysPressed, live[f].keysPressed);
        EXPECT_EQ(replayed.buttonsDown, live[f].buttonsDown);
        EXPECT_EQ(replayed.mouseDeltaX, live[f].mouseDeltaX);
        EXPECT_EQ(replayed.mouseDeltaY, live[f].mouseDeltaY);
        EXPECT_EQ(replayed.padDown, live[f].padDown);
        EXPECT_EQ(replayed.padPressed, live[f].padPressed);
        EXPECT_EQ(replayed.padAxes, live[f].padAxes);
        EXPECT_FALSE(replayed.closeRequested);
    }
    replayed.beginFrame();
    script->apply(std::uint32_t(live.size()), replayed);
    EXPECT_TRUE(replayed.closeRequested) << "the window closed: the replay ends there";
}

TEST(InputRecorder, AKeyTappedBetweenTwoFramesIsATap) {
    InputRecorder recorder;
    InputState s;
    recorder.record(0, s);
    s.beginFrame();
    s.setKey(Key::Space, true);
    s.setKey(Key::Space, false);  // down and up before the frame was made
    recorder.record(1, s);
    EXPECT_NE(recorder.text().find("1 tap Space"), std::string::npos) << recorder.text();
}

}  // namespace
}  // namespace candela::runtime
