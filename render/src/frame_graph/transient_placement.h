#pragma once
// Places transient resources in one memory pool so that two whose lifetimes overlap never
// share bytes, and two whose lifetimes do not may: largest first, each at the lowest aligned
// offset free of every already placed resource it is alive with. Pure arithmetic, no device.
#include <cstdint>
#include <span>
#include <vector>

namespace candela::render {

struct TransientInterval {
    uint64_t size = 0;
    uint64_t alignment = 1;
    int32_t first = 0;  // lifetime in pass positions, inclusive
    int32_t last = 0;
};

struct TransientPlacement {
    std::vector<uint64_t> offsets;  // per interval
    uint64_t poolBytes = 0;
    uint64_t unaliasedBytes = 0;  // what separate allocations would take (aligned sizes)
};

TransientPlacement placeTransients(std::span<const TransientInterval> intervals);

}  // namespace candela::render
