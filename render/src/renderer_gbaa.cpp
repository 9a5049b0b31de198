// GBAA's resolve in the renderer's frame (--aa gbaa; render/README.md "GBAA"): after the
// scene's passes, where TAA would resolve, the HDR target is blended across the edges the
// G-buffer pass wrote (gbuffer.edges) into a transient and copied back, so exposure, bloom,
// tonemapping and the .exr capture see the antialiased radiance.

#include <cstdint>

#include "candela/render/renderer.h"
#include "frame_graph/frame_graph.h"
#include "frame_graph/frame_graph_executor.h"
#include "frame_graph/image_copy_pass.h"
#include "passes/gbaa/gbaa_pass.h"

namespace candela::render {

uint32_t Renderer::declareGbaa(uint32_t hdrId, uint32_t hdrVersion) {
    FrameGraph& g = *graph_;
    features_.push_back("gbaa");
    ResourceHandle hdr{hdrId, hdrVersion};
    const ResourceHandle edges{edgesId_, edgesVersion_};
    ResourceHandle resolved = g.createImage(
        "gbaa.resolved", {VK_FORMAT_R32G32B32A32_SFLOAT, width_, height_, 1, false,
                          VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT});
    {
        auto p =
            g.addPass("gbaa", PassKind::Device, [this, hdr, edges, resolved](PassContext& ctx) {
                gbaaPass_->recordResolve(ctx.cmd(), ctx.image(hdr), ctx.image(edges),
                                         ctx.image(resolved));
            });
        p.read(hdr, Use::StorageRead);
        p.read(edges, Use::Sampled);
        resolved = p.write(resolved, Use::StorageWrite);
    }
    hdr = declareImageCopy(g, "gbaa_copy", resolved, hdr);
    return hdr.version;
}

}  // namespace candela::render
