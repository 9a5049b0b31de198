#include "frame_graph/transient_placement.h"

#include <algorithm>
#include <numeric>

namespace candela::render {

namespace {
uint64_t alignUp(uint64_t value, uint64_t alignment) {
    return alignment > 1 ? (value + alignment - 1) / alignment * alignment : value;
}
bool aliveTogether(const TransientInterval& a, const TransientInterval& b) {
    return a.first <= b.last && b.first <= a.last;
}
}  // namespace

TransientPlacement placeTransients(std::span<const TransientInterval> intervals) {
    TransientPlacement result;
    result.offsets.assign(intervals.size(), 0);
    std::vector<uint32_t> order(intervals.size());
    std::iota(order.begin(), order.end(), 0u);
    // Largest first (then earliest): big resources claim the low offsets, small ones fill gaps.
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        if (intervals[a].size != intervals[b].size) return intervals[a].size > intervals[b].size;
        return intervals[a].first < intervals[b].first;
    });
    std::vector<uint32_t> placed;
    std::vector<std::pair<uint64_t, uint64_t>> busy;  // [begin, end) of live-together ones
    for (uint32_t i : order) {
        const TransientInterval& r = intervals[i];
        result.unaliasedBytes = alignUp(result.unaliasedBytes, r.alignment) + r.size;
        busy.clear();
        for (uint32_t p : placed) {
            if (aliveTogether(r, intervals[p])) {
                busy.emplace_back(result.offsets[p], result.offsets[p] + intervals[p].size);
            }
        }
        std::sort(busy.begin(), busy.end());
        // Lowest aligned offset that fits between the busy ranges.
        uint64_t offset = 0;
        for (const auto& [begin, end] : busy) {
            if (alignUp(offset, r.alignment) + r.size <= begin) break;
            offset = std::max(offset, end);
        }
        offset = alignUp(offset, r.alignment);
        result.offsets[i] = offset;
        result.poolBytes = std::max(result.poolBytes, offset + r.size);
        placed.push_back(i);
    }
    return result;
}

}  // namespace candela::render
