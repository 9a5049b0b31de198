#pragma once
// CPU side of shaders/stability_checks.glsl: one record of tallies per checked quantity.
#include <bit>
#include <cstdint>
#include <cstdio>
#include <span>
#include <string>
#include <vector>

#include "compute_harness.h"

namespace candela::stability {

struct CheckRecord {
    uint32_t evaluations;
    uint32_t nanCount;
    uint32_t infCount;
    uint32_t negativeCount;
    uint32_t outOfRangeCount;
    uint32_t firstFailure;
    uint32_t maxFiniteBits;
    uint32_t pad;

    static constexpr uint32_t kNoFailure = 0xffffffffu;
    float maxFinite() const { return std::bit_cast<float>(maxFiniteBits); }
    bool failed() const { return firstFailure != kNoFailure; }
};
static_assert(sizeof(CheckRecord) == 32, "must match the std430 CheckRecord");

inline render::GpuBuffer makeCheckRecords(ComputeHarness& harness, size_t count) {
    std::vector<CheckRecord> initial(count,
                                     CheckRecord{0, 0, 0, 0, 0, CheckRecord::kNoFailure, 0, 0});
    return harness.upload(std::span<const CheckRecord>(initial));
}

inline void printCheck(const char* name, const CheckRecord& r) {
    std::printf(
        "  %-28s %10u evaluated  NaN %u  Inf %u  negative %u  out-of-range %u  max|v| %.4g\n", name,
        r.evaluations, r.nanCount, r.infCount, r.negativeCount, r.outOfRangeCount,
        double(r.maxFinite()));
}

}  // namespace candela::stability
