#pragma once
// A rendered golden capture (EXR + PNG) as the self tests load, compare and report it.
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include "engine_runner.h"
#include "golden_comparison.h"

namespace candela::golden::test {

inline const GoldenThresholds kThresholds;

struct Capture {
    LoadedHdr hdr;
    LdrImage ldr;
};

struct CaptureComparison {
    HdrComparison hdr;
    LdrComparison ldr;

    bool passed() const { return hdr.passed() && ldr.passed(); }
};

// Renders `scene` with the engine into <dir>/<name>.{exr,png} and loads both; fails the
// current test (and returns nullopt) if the engine or the files fail.
inline std::optional<Capture> renderAndLoad(const std::string& scene, const std::string& size,
                                            const std::filesystem::path& dir,
                                            const std::string& name) {
    const CommandResult run = renderCapture(scene, size, 1, dir, name);
    EXPECT_EQ(run.exitCode, 0) << run.output;
    if (run.exitCode != 0) return std::nullopt;
    std::string error;
    std::optional<LoadedHdr> hdr = readHdrExr(dir / (name + ".exr"), error);
    std::optional<LdrImage> ldr = hdr ? readLdrPng(dir / (name + ".png"), error) : std::nullopt;
    EXPECT_TRUE(hdr && ldr) << error;
    if (!hdr || !ldr) return std::nullopt;
    return Capture{*hdr, *ldr};
}

inline CaptureComparison compareCaptures(const Capture& actual, const Capture& expected) {
    return {compareHdrImages(actual.hdr, expected.hdr, kThresholds.hdr),
            compareLdrImages(actual.ldr, expected.ldr, kThresholds.ldr)};
}

// Prints the metrics, so the test log holds the measured values README.md quotes.
inline void report(const char* what, const CaptureComparison& c) {
    std::printf("[%s] %s\n  %s\n  %s\n", what, c.passed() ? "pass" : "FAIL",
                describe(c.hdr, kThresholds.hdr).c_str(), describe(c.ldr, kThresholds.ldr).c_str());
}

}  // namespace candela::golden::test
