#pragma once
// What a system sees each frame besides the world: time, input and the frame's size.
#include <cstdint>

#include "candela/runtime/input_state.h"

namespace candela::runtime {

struct FrameContext {
    std::uint32_t frame = 0;            // 0 for the first frame
    double seconds = 0.0;               // scene time at this frame
    double deltaSeconds = 0.0;          // since the previous frame (fixed step when headless)
    const InputState* input = nullptr;  // never null inside a system
    bool headless = false;
    std::uint32_t width = 0, height = 0;  // render size in pixels

    const InputState& keys() const { return *input; }
};

}  // namespace candela::runtime
