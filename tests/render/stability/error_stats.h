#pragma once
// Worst-case error bookkeeping for the accuracy tests: keeps the largest error and the input
// that produced it, so the printed report can be reproduced.
#include <cmath>
#include <cstdio>
#include <string>

namespace candela::stability {

struct WorstError {
    double error = 0.0;
    std::string where;  // the inputs of the worst case
    long count = 0;

    // describe() formats the inputs; called only for a new worst case.
    template <class Describe>
    void add(double e, Describe describe) {
        ++count;
        if (!(e <= error)) {  // also records NaN
            error = e;
            where = describe();
        }
    }
    void print(const char* name, const char* kind) const {
        std::printf("  %-34s worst %s error %.3e over %ld values at %s\n", name, kind, error, count,
                    where.c_str());
    }
};

inline double relativeError(double value, double reference) {
    if (value == reference) return 0.0;
    return std::fabs(value - reference) / std::fabs(reference);
}

}  // namespace candela::stability
