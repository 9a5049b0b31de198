#pragma once
// CPU wall time for the renderer's measurements (--stats, build timings).
#include <chrono>

namespace candela::render {

using CpuClock = std::chrono::steady_clock;

inline double millisecondsSince(CpuClock::time_point start) {
    return std::chrono::duration<double, std::milli>(CpuClock::now() - start).count();
}

}  // namespace candela::render
