#pragma once
// Hair (TressFX, Martin et al. 2014, GPU Pro 5) as a frame feature: over the lit frame, under
// the wires and blended surfaces, which then see its depth. Reads the scene targets, the lit
// inputs, the shadow maps (self-shadowing) and the froxels from the blackboard.
#include <cstdint>
#include <memory>

#include "features/render_feature.h"

namespace candela::render {

class GpuContext;
class HairPass;

class HairFeature final : public RenderFeature {
public:
    explicit HairFeature(GpuContext& context);
    ~HairFeature() override;
    bool active(const FeatureFrame& frame) const override;
    void declare(FeatureFrame& frame) override;
    // hair_nodes (the fragments the fill asked for, also work.hair_fragments),
    // hair_node_capacity, hair_nodes_dropped.
    void collectStats(RendererStats& stats, bool declared) const override;

private:
    GpuContext& context_;
    std::unique_ptr<HairPass> pass_;  // made for the first frame with hair
    bool drawn_ = false;              // the last declared frame drew hair
    uint32_t nodeCapacity_ = 0;
};

}  // namespace candela::render
