#pragma once
// Where a light can touch, in view space, from its falloff window (eq. 9 reaches zero at
// attenuationRadius): a sphere for point and sphere lights, a capsule for tubes (the window is
// measured to the nearest point of the segment), a cone for spots. Every test here is
// conservative: it may keep a light that adds nothing, never drop one that adds something.
#include <cstdint>
#include <glm/glm.hpp>

#include "candela/render/frame_scene.h"

namespace candela::render {

// HalfSphere: one-sided area lights (rect, disk), the sphere cut by the plane through its
// centre with normal segmentEnd (the emitting side is where dot(p - center, normal) >= 0).
enum class LightShape : uint8_t { Sphere, Capsule, Cone, HalfSphere };

struct LightBounds {
    glm::vec3 center{0.0f};  // bounding sphere, used for the slice and tile ranges
    float radius = 0.0f;
    LightShape shape = LightShape::Sphere;
    glm::vec3 segmentStart{0.0f};  // capsule: segment; cone: apex
    glm::vec3 segmentEnd{0.0f};    // capsule: segment end; cone: unit axis; half sphere: normal
    float capsuleRadius = 0.0f;    // capsule: attenuation radius; cone: range
    float coneCos = 0.0f;
    float coneSin = 0.0f;
};

// Bounds of a local (non-directional) light in the view space of `view`.
LightBounds lightBoundsInView(const LightInstance& light, const glm::mat4& view);

// Does the light reach the axis-aligned box [boxMin, boxMax] (view space)?
bool lightTouchesBox(const LightBounds& bounds, const glm::vec3& boxMin, const glm::vec3& boxMax);

// Which of `count` boxes (6 floats apart: min xyz, max xyz; min.x > max.x for an empty box)
// the light's bounding shape reaches, as bits from bit 0: the light itself for spheres and
// cones, the bounding sphere for capsules and half spheres (a cheap conservative test for many
// small boxes; the quarter masks of light assignment). Each box is first widened on every side by
// padPerDepth * (1 - min z), as the assignment pads pixel boxes.
uint32_t boundingShapeTouchesBoxes(const LightBounds& bounds, const float* boxes, uint32_t count,
                                   float padPerDepth);

// The bounding sphere's radius with the float slack every sphere test here adds.
float paddedBoundingRadius(const LightBounds& bounds);

// False when the light lies entirely on the negative side of the plane n.p = 0 (n unit; the
// tile side planes all pass through the camera).
bool lightReachesPositiveSide(const LightBounds& bounds, const glm::vec3& planeNormal);

}  // namespace candela::render
