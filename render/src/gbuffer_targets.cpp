#include "gbuffer_targets.h"

namespace candela::render {

GBufferTargets::GBufferTargets(GpuContext& context, uint32_t width, uint32_t height) {
    for (size_t i = 0; i < color.size(); ++i) {
        color[i] =
            GpuImage(context, {kColorFormats[i], width, height, 1, false,
                               VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT});
    }
    depth = GpuImage(context,
                     {kDepthFormat, width, height, 1, false,
                      VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT});
}

}  // namespace candela::render
