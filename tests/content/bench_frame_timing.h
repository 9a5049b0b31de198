#pragma once
// How candela-bench-animation and its ozz-animation side-by-side program
// (ozz_side_by_side/ozz_fox_bench.cpp) time a crowd's frame, shared so the two measure alike.
// Header only, without Candela's headers: the ozz program is built outside Candela's build.
#include <algorithm>
#include <ctime>
#include <vector>

namespace candela::bench {

// Thread CPU time in ns: the development machine is shared, so wall time would count other
// jobs. A read is a system call of about 0.5 us here, which each timed interval carries once.
inline double threadCpuNs() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) * 1e9 + static_cast<double>(t.tv_nsec);
}

// The median (the upper middle value of an even count).
inline double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// Frames per timed interval for the whole frame: about 1,000 Foxes' worth, so the clock's
// two reads are a small share of what is timed at every size (a one-Fox frame is about as
// long as a read).
inline int framesPerClockPair(int foxes) {
    return std::max(1, 1000 / foxes);
}

}  // namespace candela::bench
