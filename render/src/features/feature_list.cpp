#include "features/feature_list.h"

#include <utility>

namespace candela::render {

void FeatureList::add(FeatureRun run, std::unique_ptr<RenderFeature> feature) {
    entries_.push_back({std::move(feature), run, false});
}

void FeatureList::declareRun(FeatureFrame& frame, FeatureRun run) {
    for (Entry& e : entries_) {
        if (e.run != run) continue;
        e.declared = e.feature->active(frame);
        if (e.declared) {
            e.feature->declare(frame);
        } else {
            e.feature->restartHistory();
        }
    }
}

void FeatureList::sitOut() {
    for (Entry& e : entries_)
        e.declared = false;
    restartHistories();
}

void FeatureList::restartHistories() {
    for (Entry& e : entries_)
        e.feature->restartHistory();
}

void FeatureList::collectStats(RendererStats& stats, bool recorded) const {
    for (const Entry& e : entries_)
        e.feature->collectStats(stats, recorded && e.declared);
}

}  // namespace candela::render
