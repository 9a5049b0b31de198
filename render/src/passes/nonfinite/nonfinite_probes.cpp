#include "passes/nonfinite/nonfinite_probes.h"

#include <algorithm>
#include <string>

#include "frame_graph/frame_graph_executor.h"
#include "passes/nonfinite/nonfinite_pass.h"

namespace candela::render {

bool probeableImage(const ImageDesc& desc) {
    if (desc.cube || desc.samples != VK_SAMPLE_COUNT_1_BIT) return false;
    switch (desc.format) {
        case VK_FORMAT_R16_SFLOAT:
        case VK_FORMAT_R16G16_SFLOAT:
        case VK_FORMAT_R16G16B16A16_SFLOAT:
        case VK_FORMAT_R32_SFLOAT:
        case VK_FORMAT_R32G32_SFLOAT:
        case VK_FORMAT_R32G32B32A32_SFLOAT:
        case VK_FORMAT_B10G11R11_UFLOAT_PACK32:
            return true;
        default:
            return false;
    }
}

namespace {

// A transient a pass writes only in part (the SSR colour pyramid's levels packed in one image)
// would show its unwritten texels' garbage to a probe: in a diagnosis frame every probed
// transient is cleared to zero first. Its uses move up a version; the clear writes version 0.
void clearFirst(FrameGraph& graph, uint32_t resource) {
    for (PassDecl& p : graph.passes()) {
        for (UseDecl& use : p.uses) {
            if (use.resource == resource) ++use.version;
        }
    }
    graph.resources()[resource].imageDesc.usage |= VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    const ResourceHandle image{resource, 0};
    auto clear = graph.addPass("nonfinite_clear", PassKind::Device, [image](PassContext& ctx) {
        const VkClearColorValue zero{};
        const VkImageSubresourceRange all{VK_IMAGE_ASPECT_COLOR_BIT, 0, VK_REMAINING_MIP_LEVELS, 0,
                                          VK_REMAINING_ARRAY_LAYERS};
        vkCmdClearColorImage(ctx.cmd(), ctx.image(image).handle(),
                             VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &zero, 1, &all);
    });
    clear.write(image, Use::TransferDst, 0);
}

// The image a device pass's write makes probeable, or null.
const ImageDesc* probedImage(const FrameGraph& graph, const PassDecl& writer, const UseDecl& use) {
    if (writer.kind != PassKind::Device || !useInfo(use.use, use.shaderStages).writes) {
        return nullptr;
    }
    const ResourceDecl& resource = graph.resources()[use.resource];
    if (!resource.image || (resource.imported && !resource.importedImage)) return nullptr;
    const ImageDesc& desc = resource.imported ? resource.importedImage->desc() : resource.imageDesc;
    return probeableImage(desc) ? &desc : nullptr;
}

}  // namespace

std::vector<NonFiniteProbe> addNonFiniteProbes(FrameGraph& graph, const NonFinitePass& pass,
                                               uint32_t firstSlot, uint32_t slotCount) {
    const size_t declared = graph.passes().size();  // not the passes this adds
    // Transients first: made sampled and cleared before their first use.
    std::vector<bool> transient(graph.resources().size(), false);
    for (uint32_t p = 0; p < declared; ++p) {
        for (const UseDecl& use : graph.passes()[p].uses) {
            if (probedImage(graph, graph.passes()[p], use) &&
                !graph.resources()[use.resource].imported) {
                transient[use.resource] = true;
            }
        }
    }
    for (uint32_t r = 0; r < transient.size(); ++r) {
        if (!transient[r]) continue;
        graph.resources()[r].imageDesc.usage |= VK_IMAGE_USAGE_SAMPLED_BIT;
        clearFirst(graph, r);
    }
    std::vector<NonFiniteProbe> probes;
    uint32_t slot = firstSlot;
    for (uint32_t p = 0; p < declared && slot < slotCount; ++p) {
        // Copies: adding passes and resources below reallocates the graph's arrays.
        const PassDecl writer = graph.passes()[p];
        for (const UseDecl& use : writer.uses) {
            const ImageDesc* desc = probedImage(graph, writer, use);
            if (!desc || slot >= slotCount) continue;
            // An RGBA32F storage image (the HDR target) is read as storage, in the GENERAL
            // layout its passes keep it in; anything else through a sampler.
            const bool storage = desc->format == VK_FORMAT_R32G32B32A32_SFLOAT &&
                                 (desc->usage & VK_IMAGE_USAGE_STORAGE_BIT);
            if (!storage && !(desc->usage & VK_IMAGE_USAGE_SAMPLED_BIT)) continue;
            const ResourceHandle image{use.resource, use.version + 1};
            const std::string imageName = graph.resources()[use.resource].name;
            const ResourceHandle count =
                graph.importBuffer("nonfinite.probe" + std::to_string(slot), &pass.counts(), true);
            auto probe =
                graph.addPass("nonfinite_probe", PassKind::Device,
                              [&pass, image, slot, storage](PassContext& ctx) {
                                  pass.recordCount(ctx.cmd(), ctx.image(image), slot, storage);
                              });
            probe.read(image, storage ? Use::StorageRead : Use::Sampled);
            probe.write(count, Use::StorageReadWrite);
            probe.sideEffect();
            probes.push_back({slot, p, writer.name, imageName});
            ++slot;
        }
    }
    return probes;
}

const NonFiniteProbe* firstNonFiniteProbe(const std::vector<NonFiniteProbe>& probes,
                                          const std::vector<uint32_t>& counts,
                                          const std::vector<uint32_t>& executionOrder) {
    const NonFiniteProbe* first = nullptr;
    size_t firstPosition = SIZE_MAX;
    for (size_t i = 0; i < probes.size() && i < counts.size(); ++i) {
        if (counts[i] == 0) continue;
        auto at = std::find(executionOrder.begin(), executionOrder.end(), probes[i].writerPass);
        const size_t position = size_t(at - executionOrder.begin());
        if (position < firstPosition) {
            firstPosition = position;
            first = &probes[i];
        }
    }
    return first;
}

}  // namespace candela::render
