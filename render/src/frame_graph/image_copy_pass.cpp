#include "frame_graph/image_copy_pass.h"

#include "frame_graph/frame_graph_executor.h"

namespace candela::render {

ResourceHandle declareImageCopy(FrameGraph& graph, const char* name, ResourceHandle source,
                                ResourceHandle target) {
    auto p = graph.addPass(name, PassKind::Device, [source, target](PassContext& ctx) {
        const ImageRef from = ctx.image(source);
        const ImageRef to = ctx.image(target);
        VkImageCopy region{};
        region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.extent = {to.desc().width, to.desc().height, 1};
        vkCmdCopyImage(ctx.cmd(), from.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, to.handle(),
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    });
    p.read(source, Use::TransferSrc);
    return p.write(target, Use::TransferDst);
}

}  // namespace candela::render
