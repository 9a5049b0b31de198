#pragma once
// What the renderer declared for the last frame: the blackboard its features filled, the
// features it enabled (--stats "features"), the work its declaration fixed (froxel pairs, AO
// samples; collectStats adds the passes' counters) and what it drew.
#include <cstdint>
#include <string>
#include <vector>

#include "candela/render/renderer_options.h"
#include "features/frame_blackboard.h"

namespace candela::render {

enum class RecordedFrame : uint8_t { None, TestTriangle, Scene };

struct DeclaredFrame {
    FrameBlackboard board;
    std::vector<std::string> features;
    WorkCounters work;
    RecordedFrame recorded = RecordedFrame::None;
};

}  // namespace candela::render
