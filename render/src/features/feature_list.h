#pragma once
// The renderer's features in frame order, each with the run it declares in and whether the last
// declared frame declared it.
#include <memory>
#include <vector>

#include "features/render_feature.h"

namespace candela::render {

class FeatureList {
public:
    void add(FeatureRun run, std::unique_ptr<RenderFeature> feature);
    // The active features of `run` declare their passes, in the order they were added; the
    // others restart their history (a frame without them breaks their sequence).
    void declareRun(FeatureFrame& frame, FeatureRun run);
    // A frame without the scene (the test triangle): every feature sits it out.
    void sitOut();
    // A camera cut or a resize: every feature's temporal state starts again.
    void restartHistories();
    // Each feature's stats for the last frame; `recorded`: whether a frame was recorded at all.
    void collectStats(RendererStats& stats, bool recorded) const;
    // The feature of type T, or null.
    template <class T>
    T* find() const {
        for (const Entry& e : entries_) {
            if (auto* feature = dynamic_cast<T*>(e.feature.get())) return feature;
        }
        return nullptr;
    }

private:
    struct Entry {
        std::unique_ptr<RenderFeature> feature;
        FeatureRun run;
        bool declared = false;
    };
    std::vector<Entry> entries_;
};

}  // namespace candela::render
