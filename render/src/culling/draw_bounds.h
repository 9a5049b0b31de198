#pragma once
// A draw's world-space box: what culling tests against a view's frustum and what shadow maps
// fit their casters by.
#include <glm/vec3.hpp>
#include <vector>

namespace candela::render {

struct DrawItem;
struct FrameScene;
class SceneResources;

struct WorldBounds {
    glm::vec3 centre{0.0f};
    glm::vec3 extent{0.0f};  // half size along the world axes
    float radius = 0.0f;     // of the sphere around the box
};

// The draw's mesh-space box (a skinned draw's pose this frame, else its mesh's) carried into
// world space: the axis-aligned box around the transformed box (Arvo 1990, "Transforming
// Axis-Aligned Bounding Boxes", Graphics Gems).
WorldBounds worldBoundsOf(const DrawItem& draw, const SceneResources& resources);
// Every draw's of `scene`, in its order: computed once a frame, read by the camera's culling
// and the shadow views'.
std::vector<WorldBounds> worldBoundsOf(const FrameScene& scene, const SceneResources& resources);

}  // namespace candela::render
