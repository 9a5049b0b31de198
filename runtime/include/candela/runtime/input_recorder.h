#pragma once
// Records what a run's input did, frame by frame, as an input script (input_script.h) that
// --input replays: keys, mouse buttons and motion, gamepad buttons and sticks, and the window
// closing. `--record-input FILE.input` records a windowed session; such a run takes the fixed
// step, as a replay does, so the replay sees the same frames.
//
//   InputRecorder recorder;
//   recorder.record(frame, input);  // after the frame's input is gathered
//   std::string error = recorder.write("session.input");
#include <cstdint>
#include <filesystem>
#include <string>

#include "candela/runtime/input_state.h"

namespace candela::runtime {

class InputRecorder {
public:
    // Compares `state` with the previous frame's and appends a line per change. A key that went
    // down and up again within the frame is a `tap`.
    void record(std::uint32_t frame, const InputState& state);
    // The run ended before `frame` rendered because the window closed: a `quit` line.
    void recordQuit(std::uint32_t frame);
    const std::string& text() const { return text_; }
    // Atomically; empty on success, else "<path>: cannot write: <error>".
    std::string write(const std::filesystem::path& path) const;

private:
    InputState last_;
    std::string text_ = "# recorded by --record-input\n";
};

}  // namespace candela::runtime
