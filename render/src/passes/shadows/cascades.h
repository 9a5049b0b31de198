#pragma once
// Directional shadow cascades: the practical split scheme, each slice of the view frustum
// bounded by a sphere, and the sphere's orthographic shadow view snapped to whole texels in
// light space, so a camera that moves or turns leaves every texel's footprint where it was
// (render/README.md "Shadows"). CPU only, unit-tested without a device.
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "candela/render/frame_scene.h"

namespace candela::render {

// Split distances (view depth) of `count` cascades over [near, far]: lambda blends the
// logarithmic scheme (1) with the uniform one (0) (Zhang et al. 2006). count + 1 entries.
std::vector<float> practicalSplits(float nearPlane, float farPlane, uint32_t count, float lambda);
// The renderer's lambda: mostly logarithmic, so the first cascade stays sharp near the camera.
inline constexpr float kPracticalSplitLambda = 0.75f;

struct CascadeView {
    glm::mat4 worldToClip{1.0f};  // orthographic, reversed linear depth in [0, 1]
    glm::vec4 sphere{0.0f};       // world centre and radius of what the cascade covers
    float texelWorld = 0.0f;      // metres per shadow texel
    float nearDepth = 0.0f;       // light-space depth of clip z 1 ...
    float farDepth = 0.0f;        // ... and of clip z 0
};

// An orthonormal basis whose third axis is `direction` (where the light travels), chosen the
// same way for the same direction every frame.
glm::mat3 lightBasis(const glm::vec3& direction);

// The cascade of the view-depth slice [sliceNear, sliceFar] of `camera` (a perspective
// projection), rendered at `resolution` texels, for a light travelling along `direction`.
// `casterNear`: the smallest light-space depth of any caster (dot(position, direction)), so
// casters between the light and the slice are kept.
CascadeView fitCascade(const CameraView& camera, float sliceNear, float sliceFar,
                       const glm::vec3& direction, uint32_t resolution, float casterNear);

}  // namespace candela::render
