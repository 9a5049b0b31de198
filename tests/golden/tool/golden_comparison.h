#pragma once
// The verdict of a golden comparison: metrics plus the list of thresholds they broke.
// HDR and PNG are judged separately; a golden test needs both to pass.
#include <cstdint>
#include <string>
#include <vector>

#include "golden_thresholds.h"
#include "image_files.h"
#include "image_metrics.h"
#include "ssim.h"

namespace candela::golden {

struct HdrComparison {
    bool sameSize = false;
    DifferenceStats difference;
    std::uint64_t actualNonFiniteTexels = 0;
    std::uint64_t expectedNonFiniteTexels = 0;
    std::vector<std::string> failures;  // one sentence per broken threshold; empty: pass

    bool passed() const { return failures.empty(); }
};

struct LdrComparison {
    bool sameSize = false;
    DifferenceStats difference;
    SsimResult ssim;
    std::vector<std::string> failures;

    bool passed() const { return failures.empty(); }
};

HdrComparison compareHdrImages(const LoadedHdr& actual, const LoadedHdr& expected,
                               const HdrThresholds& thresholds);
LdrComparison compareLdrImages(const LdrImage& actual, const LdrImage& expected,
                               const LdrThresholds& thresholds);

// One line of metrics each, printed whether the comparison passed or not.
std::string describe(const HdrComparison& comparison, const HdrThresholds& thresholds);
std::string describe(const LdrComparison& comparison, const LdrThresholds& thresholds);

}  // namespace candela::golden
