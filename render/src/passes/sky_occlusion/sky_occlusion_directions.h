#pragma once
// The directions over the sky hemisphere that sky occlusion renders a depth map from, and the
// orthographic view of each over the scene's bounding sphere (render/README.md "Sky
// occlusion"). common/sky_occlusion.glsl computes the same directions and views in the
// shaders, so only the sphere and the atlas layout travel to the device (GpuCamera). CPU only,
// unit-tested without a device.
#include <cstdint>
#include <glm/glm.hpp>

namespace candela::render {

// Direction i of n (y up): equal-area over the upper hemisphere (y = (i + 1/2) / n, a golden-
// angle spiral in azimuth), so each stands for 2 pi / n steradians.
glm::vec3 skyOcclusionDirection(uint32_t i, uint32_t n);

// World to clip of direction d's view of the sphere (centre, radius): x, y span the sphere's
// square across d; z (stored depth, 0..1) grows toward the sky over [-radius, 3 radius] along
// d, so the highest surface of a texel's column wins a GREATER depth test (cleared to 0).
glm::mat4 skyOcclusionView(const glm::vec3& d, const glm::vec3& centre, float radius);

}  // namespace candela::render
