#pragma once
// A looping camera path through keyframes (position and a point to look at), evaluated by
// time alone so a headless run sees the same views every time.
#include <vector>

#include "candela/ecs/transform_math.h"

namespace candela::runtime {

struct CameraKey {
    ecs::Vec3 position;
    ecs::Vec3 target;  // the point the camera looks at
};

struct CameraPose {
    ecs::Vec3 position;
    ecs::Quat rotation;  // camera looks along its -Z, +Y up
};

class CameraPath {
public:
    // At least two keys; `secondsPerKey` between consecutive keys (the loop closes back to
    // the first key).
    CameraPath(std::vector<CameraKey> keys, float secondsPerKey);

    float loopSeconds() const { return float(keys_.size()) * secondsPerKey_; }
    // Catmull-Rom through the keys (positions and targets alike), wrapping at the loop.
    CameraPose pose(double seconds) const;

private:
    std::vector<CameraKey> keys_;
    float secondsPerKey_;
};

// The rotation that makes a camera at `position` look at `target` with +Y up.
ecs::Quat lookAtRotation(ecs::Vec3 position, ecs::Vec3 target);

}  // namespace candela::runtime
