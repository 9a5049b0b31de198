#pragma once
// Clears the HDR target and draws one flat-colour triangle (the foundation test scene).
#include <array>

#include "candela/render/pipeline.h"
#include "frame_graph/graph_resources.h"

namespace candela::render {

class GpuContext;

// NDC corners of the triangle, shared with tests that check coverage pixel by pixel.
inline constexpr std::array<std::array<float, 2>, 3> kTestTriangleNdc = {
    {{0.0f, -0.6f}, {0.6f, 0.6f}, {-0.6f, 0.6f}}};

class TrianglePass {
public:
    explicit TrianglePass(GpuContext& context);
    // target must be in COLOR_ATTACHMENT_OPTIMAL layout.
    void record(VkCommandBuffer cmd, const ImageRef& target, const std::array<float, 4>& clear,
                const std::array<float, 4>& radiance) const;

private:
    Pipeline pipeline_;
};

}  // namespace candela::render
