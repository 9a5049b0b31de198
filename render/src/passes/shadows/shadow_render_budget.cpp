#include "passes/shadows/shadow_render_budget.h"

#include <algorithm>

namespace candela::render {

std::vector<ShadowRenderChoice> planShadowRenders(std::span<const ShadowRenderCandidate> lights,
                                                  uint64_t budgetTexels) {
    std::vector<ShadowRenderChoice> choice(lights.size(), ShadowRenderChoice::Cached);
    uint64_t spent = 0;
    std::vector<size_t> deferrable;
    for (size_t i = 0; i < lights.size(); ++i) {
        if (!lights[i].changed) continue;
        if (budgetTexels == 0 || !lights[i].keepable) {
            // No budget, or nothing valid to keep: rendering is the only way to a correct map.
            choice[i] = ShadowRenderChoice::Render;
            spent += lights[i].texels;
        } else {
            deferrable.push_back(i);
        }
    }
    std::stable_sort(deferrable.begin(), deferrable.end(), [&](size_t a, size_t b) {
        if (lights[a].framesWaiting != lights[b].framesWaiting)
            return lights[a].framesWaiting > lights[b].framesWaiting;
        return lights[a].priority > lights[b].priority;
    });
    for (size_t k = 0; k < deferrable.size(); ++k) {
        const size_t i = deferrable[k];
        // The first (longest waiting) always renders: progress every frame, even over budget.
        const bool fits = spent + lights[i].texels <= budgetTexels;
        if (k == 0 || fits) {
            choice[i] = ShadowRenderChoice::Render;
            spent += lights[i].texels;
        } else {
            choice[i] = ShadowRenderChoice::Keep;
        }
    }
    return choice;
}

}  // namespace candela::render
