#pragma once
// This frame's shadow maps in its graph (published only when a light casts).
#include "frame_graph/frame_graph.h"

namespace candela::render {

class ShadowPass;

struct ShadowFrame {
    const ShadowPass* pass;  // its atlas and views, read when passes record
    ResourceHandle atlas, views, lights;
};

}  // namespace candela::render
