#pragma once
// The median of a set of timings (the upper one of an even count): what the benchmarks and the
// speed-against-error report quote, since these machines are noisy.
#include <algorithm>
#include <vector>

namespace candela {

inline double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values.empty() ? 0.0 : values[values.size() / 2];
}

}  // namespace candela
