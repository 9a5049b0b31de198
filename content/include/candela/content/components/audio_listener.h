#pragma once
// AudioListener component: the ears spatial sounds are heard by, at the entity's world pose
// (facing its -Z, up its +Y, like a camera). One per scene; without one, the active camera
// listens.
//
//   "audioListener": {}
namespace candela::content {

struct AudioListener {
    float gain = 1.0f;  // master volume, linear, >= 0

    bool operator==(const AudioListener&) const = default;
};

}  // namespace candela::content
