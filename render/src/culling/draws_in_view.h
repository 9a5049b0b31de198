#pragma once
// What a view draws of each of a frame's draws: nothing, when its world box lies outside the
// view's frustum, else a level of detail. The G-buffer and forward passes skip the rest; on a
// CPU rasterizer every vertex of a draw off screen would still be transformed.
#include <cstdint>
#include <span>
#include <vector>

#include "culling/lod_selection.h"
#include "culling/view_frustum.h"

namespace candela::render {

struct FrameScene;

inline constexpr uint8_t kDrawCulled = 0xFF;

// Per draw of `scene` (`bounds`: their world boxes, worldBoundsOf): kDrawCulled, or the level
// of detail `lod` picks (selectLod).
std::vector<uint8_t> drawsInView(const FrameScene& scene, const SceneResources& resources,
                                 std::span<const WorldBounds> bounds, const ViewFrustum& frustum,
                                 const LodView& lod);

}  // namespace candela::render
