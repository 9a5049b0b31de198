#include "passes/bloom/bloom_feature.h"

#include <array>
#include <string>

#include "features/scene_targets.h"
#include "frame_graph/frame_graph_executor.h"
#include "passes/bloom/bloom_pass.h"

namespace candela::render {

BloomFeature::BloomFeature(GpuContext& context) : context_(context) {}

BloomFeature::~BloomFeature() = default;

bool BloomFeature::active(const FeatureFrame& frame) const {
    return frame.options.bloomStrength > 0.0f;
}

void BloomFeature::declare(FeatureFrame& frame) {
    frame.features.push_back("bloom");
    if (!pass_) pass_ = std::make_unique<BloomPass>(context_);
    const BloomPass* pass = pass_.get();
    FrameGraph& g = frame.graph;
    SceneTargets& targets = frame.board.get<SceneTargets>();
    const uint32_t levelCount = BloomPass::levelCount(frame.width, frame.height);
    std::array<ResourceHandle, BLOOM_MAX_LEVELS> levels{};
    ResourceHandle source = targets.hdr;
    for (uint32_t i = 0; i < levelCount; ++i) {
        ResourceHandle level = g.createImage("bloom.level" + std::to_string(i),
                                             BloomPass::levelDesc(i, frame.width, frame.height));
        auto p =
            g.addPass("bloom_down" + std::to_string(i), PassKind::Device,
                      [pass, source, level](PassContext& ctx) {
                          pass->recordDownsample(ctx.cmd(), ctx.image(source), ctx.image(level));
                      });
        p.read(source, Use::StorageRead);
        levels[i] = p.write(level, Use::StorageWrite);
        source = levels[i];
    }
    const ResourceHandle hdr = targets.hdr;
    const float strength = frame.options.bloomStrength;
    auto p = g.addPass("bloom_composite", PassKind::Device,
                       [pass, hdr, levels, levelCount, strength](PassContext& ctx) {
                           std::array<ImageRef, BLOOM_MAX_LEVELS> images{};
                           for (uint32_t i = 0; i < levelCount; ++i)
                               images[i] = ctx.image(levels[i]);
                           pass->recordComposite(ctx.cmd(), ctx.image(hdr), images, levelCount,
                                                 strength);
                       });
    for (uint32_t i = 0; i < levelCount; ++i)
        p.read(levels[i], Use::Sampled);
    targets.hdr = p.write(hdr, Use::StorageReadWrite);
}

void BloomFeature::collectStats(RendererStats& stats, bool) const {
    stats.bloomMs = passMilliseconds(stats, "bloom_");
}

}  // namespace candela::render
