#pragma once
// A technique of the frame (hair, wires, ...) owning its passes, its state and its stats behind
// one small interface. The renderer keeps them in frame order; every frame it asks each whether
// the scene needs it, and those that answer yes declare their passes into the frame graph,
// reading what earlier features published on the blackboard and publishing their own. Adding a
// technique is a folder with its feature and one line in Renderer's feature list.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "candela/render/renderer_options.h"
#include "features/frame_blackboard.h"
#include "frame_graph/frame_graph.h"
#include "passes/lighting/lighting_pass.h"  // LightingFeatures

namespace candela::render {

class GpuContext;
class SceneResources;
struct FrameInputs;

// What a feature sees of the frame it declares into.
struct FeatureFrame {
    FrameGraph& graph;
    const FrameInputs& inputs;
    SceneResources& resources;
    const RendererOptions& options;
    uint32_t width, height;            // the render size
    const LightingFeatures& lighting;  // the frame's shading variant (shadows, sky, clusters)
    FrameBlackboard& board;
    std::vector<std::string>& features;  // --stats "features": a feature adds what it drew
    WorkCounters& work;                  // counts fixed when the frame is declared
};

// Where in the frame a feature declares its passes, around those the renderer still declares
// itself (render/README.md, "Features that own themselves").
enum class FeatureRun : uint8_t {
    BeforeGeometry,  // before shadow maps and the G-buffer: skinning
    BeforeLighting,  // between the G-buffer and lighting: ambient occlusion
    OverLitFrame,    // over the lit frame, under blended surfaces: SSR, media, hair, wires
    AfterScene,      // on the scene's HDR target: antialiasing, exposure, bloom
};

// The GPU time of the last frame's passes whose names start with `prefix` (stats.passMs): what a
// feature reports for the passes it names.
inline double passMilliseconds(const RendererStats& stats, std::string_view prefix) {
    double ms = 0.0;
    for (const auto& [name, passMs] : stats.passMs) {
        if (name.starts_with(prefix)) ms += passMs;
    }
    return ms;
}

class RenderFeature {
public:
    virtual ~RenderFeature() = default;
    // Whether this frame's scene has anything for the feature (no passes, no images otherwise).
    virtual bool active(const FeatureFrame& frame) const = 0;
    virtual void declare(FeatureFrame& frame) = 0;
    // After the frame completed; `declared`: the frame declared this feature's passes.
    virtual void collectStats(RendererStats& stats, bool declared) const {
        (void)stats;
        (void)declared;
    }
    // A camera cut, a resize or a frame the feature sat out: temporal state starts again.
    virtual void restartHistory() {}
};

}  // namespace candela::render
