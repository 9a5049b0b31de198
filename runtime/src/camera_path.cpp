#include "candela/runtime/camera_path.h"

#include <cmath>
#include <stdexcept>

namespace candela::runtime {

namespace {

ecs::Vec3 catmullRom(ecs::Vec3 p0, ecs::Vec3 p1, ecs::Vec3 p2, ecs::Vec3 p3, float t) {
    const float t2 = t * t, t3 = t2 * t;
    return 0.5f * ((2.0f * p1) + (p2 - p0) * t + (2.0f * p0 - 5.0f * p1 + 4.0f * p2 - p3) * t2 +
                   (3.0f * p1 - p0 - 3.0f * p2 + p3) * t3);
}

}  // namespace

CameraPath::CameraPath(std::vector<CameraKey> keys, float secondsPerKey)
    : keys_(std::move(keys)), secondsPerKey_(secondsPerKey) {
    if (keys_.size() < 2) throw std::invalid_argument("CameraPath needs at least two keys");
    if (!(secondsPerKey_ > 0.0f)) {
        throw std::invalid_argument("CameraPath needs a positive time between keys");
    }
}

CameraPose CameraPath::pose(double seconds) const {
    const double loop = double(loopSeconds());
    double t = std::fmod(seconds, loop);
    if (t < 0.0) t += loop;
    const double along = t / double(secondsPerKey_);
    const size_t n = keys_.size();
    const size_t i = size_t(along) % n;
    const float f = float(along - std::floor(along));
    const CameraKey& k0 = keys_[(i + n - 1) % n];
    const CameraKey& k1 = keys_[i];
    const CameraKey& k2 = keys_[(i + 1) % n];
    const CameraKey& k3 = keys_[(i + 2) % n];
    CameraPose pose;
    pose.position = catmullRom(k0.position, k1.position, k2.position, k3.position, f);
    ecs::Vec3 target = catmullRom(k0.target, k1.target, k2.target, k3.target, f);
    pose.rotation = lookAtRotation(pose.position, target);
    return pose;
}

ecs::Quat lookAtRotation(ecs::Vec3 position, ecs::Vec3 target) {
    ecs::Vec3 d = target - position;
    float len = ecs::length(d);
    if (len <= 0.0f) return {};
    d *= 1.0f / len;
    // Yaw about +Y, then pitch about the camera's +X; the camera looks along -Z.
    const float yaw = std::atan2(-d.x, -d.z);
    const float pitch = std::asin(std::fmax(-1.0f, std::fmin(1.0f, d.y)));
    return ecs::normalize(ecs::Quat::fromAxisAngle({0.0f, 1.0f, 0.0f}, yaw) *
                          ecs::Quat::fromAxisAngle({1.0f, 0.0f, 0.0f}, pitch));
}

}  // namespace candela::runtime
