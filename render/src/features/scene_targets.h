#pragma once
// The scene's targets at the render size, as the frame's passes have written them so far: a
// feature that draws into them declares its pass's write and stores the new version back.
#include "frame_graph/frame_graph.h"

namespace candela::render {

struct SceneTargets {
    ResourceHandle hdr;     // radiance, RGBA32F
    ResourceHandle depth;   // reverse-Z
    ResourceHandle motion;  // RG16F screen-space motion
    ResourceHandle camera;  // the camera uniform block
};

}  // namespace candela::render
