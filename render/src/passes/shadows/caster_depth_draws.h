#pragma once
// Draws casters into a depth view (a shadow map's tile, a sky-occlusion map's tile): the
// bound depth-only pipeline (shadow_depth.vert) takes each draw's world-to-clip matrix as
// its push constant; skinned and morphed draws cast with this frame's deformed vertices, each
// caster at its level of detail in `lods` (empty: every one in full).
#include <vulkan/vulkan.h>

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <span>

namespace candela::render {

class Pipeline;
class SceneResources;
struct FrameScene;

void drawCasterDepths(VkCommandBuffer cmd, const Pipeline& pipeline, const FrameScene& scene,
                      const SceneResources& resources, std::span<const uint32_t> casters,
                      const glm::mat4& viewToClip, std::span<const uint8_t> lods = {});

}  // namespace candela::render
