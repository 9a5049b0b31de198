#pragma once
// What `candela-golden` does, as functions the tests call directly. Each returns the exit
// code: 0 pass, 1 the images differ (or a golden is missing), 2 inputs unusable.
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>

#include "golden_thresholds.h"

namespace candela::golden {

inline constexpr int kExitPass = 0;
inline constexpr int kExitDiffers = 1;
inline constexpr int kExitUnusable = 2;

struct CheckRequest {
    std::string name;
    std::filesystem::path actualDir;    // holds <name>.exr and <name>.png from the run
    std::filesystem::path expectedDir;  // holds the stored <name>.exr and <name>.png
    std::filesystem::path outputDir;    // where failures write their images; empty: actualDir
    GoldenThresholds thresholds;
};

// Compares both captures with their goldens and prints the metrics. On failure writes
// <name>.expected.{exr,png}, <name>.diff-hdr.png and <name>.diff-png.png to the output
// directory and prints their absolute paths.
int checkGolden(const CheckRequest& request, std::ostream& out);

// Compares two .exr or two .png files with the golden thresholds; optionally writes the
// false-colour diff.
int compareImageFiles(const std::filesystem::path& actual, const std::filesystem::path& expected,
                      const std::optional<std::filesystem::path>& diffPng,
                      const GoldenThresholds& thresholds, std::ostream& out);

// Prints size and luminance range of an EXR; fails on NaN/Inf (kept out of goldens).
int inspectExr(const std::filesystem::path& path, std::ostream& out);

}  // namespace candela::golden
