#pragma once
// Plain CPU skinning and morphing of one primitive, the reference the GPU pass
// (render/src/passes/skinning) is tested against, and a fallback for tools: morph deltas first,
// then linear blend skinning with the joint matrices (bind-pose mesh space -> current mesh
// space, Skin::jointMatrices). Normals and tangents are renormalised; a tangent's w (bitangent
// sign) is kept.
#include <span>
#include <vector>

#include "candela/content/model.h"
#include "candela/ecs/transform_math.h"

namespace candela::content {

struct DeformedVertices {
    std::vector<Float3> positions;
    std::vector<Float3> normals;
    std::vector<Float4> tangents;  // empty when the primitive has none
};

// `jointMatrices` empty: no skinning; `morphWeights` empty: no morphing.
void deformPrimitive(const Primitive& primitive, std::span<const ecs::Mat4> jointMatrices,
                     std::span<const float> morphWeights, DeformedVertices& out);

}  // namespace candela::content
