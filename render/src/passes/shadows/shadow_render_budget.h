#pragma once
// Which lights re-render their shadow maps this frame under a per-frame budget of texels
// (RendererOptions::shadowRenderBudget). A light whose views or casters changed renders, unless
// the budget is spent and its last maps are still in the atlas at the same tiles: then it keeps
// them for this frame (stale by a frame or more, never missing or broken). Lights that have
// waited longest go first, then the most important; the longest-waiting one renders every
// frame even over budget, so none waits forever. CPU only, unit-tested without a device.
#include <cstdint>
#include <span>
#include <vector>

namespace candela::render {

struct ShadowRenderCandidate {
    uint64_t texels = 0;         // texels of its tiles this frame
    bool changed = false;        // its views or casters differ from what its maps hold
    bool keepable = false;       // its last maps are in the atlas at this frame's tiles
    float priority = 0.0f;       // importance (larger first among equally waiting)
    uint32_t framesWaiting = 0;  // frames it has already kept stale maps
};

enum class ShadowRenderChoice {
    Cached,  // nothing changed: the maps in the atlas are current
    Render,  // render this frame
    Keep,    // changed but over budget: last frame's maps stay
};

// budgetTexels 0: no budget (every changed light renders). Lights that must render (changed,
// not keepable) count against the budget first.
std::vector<ShadowRenderChoice> planShadowRenders(std::span<const ShadowRenderCandidate> lights,
                                                  uint64_t budgetTexels);

}  // namespace candela::render
