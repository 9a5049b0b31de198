#pragma once
// Deterministic low-discrepancy points (Halton sequence) for the accuracy tests' inputs: the
// same inputs on every run and platform, spread evenly over the input domain.
#include <array>
#include <cstdint>

namespace candela::stability {

inline double radicalInverse(uint32_t index, uint32_t base) {
    double result = 0.0;
    double digitWeight = 1.0 / base;
    while (index > 0) {
        result += (index % base) * digitWeight;
        index /= base;
        digitWeight /= base;
    }
    return result;
}

// Point `index` of the Halton sequence in D dimensions, in [0, 1)^D.
template <size_t D>
std::array<double, D> halton(uint32_t index) {
    static constexpr std::array<uint32_t, 8> kPrimes = {2, 3, 5, 7, 11, 13, 17, 19};
    static_assert(D <= kPrimes.size());
    std::array<double, D> point{};
    for (size_t d = 0; d < D; ++d)
        point[d] = radicalInverse(index + 1, kPrimes[d]);
    return point;
}

}  // namespace candela::stability
