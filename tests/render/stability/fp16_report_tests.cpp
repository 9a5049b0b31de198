// Writes FP16_REPORT.md (where the shared terms break in half precision) and checks that the
// scan finds the limits that follow analytically from binary16's range and spacing.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "fp16_report.h"

using namespace candela::stability;

namespace {

const std::vector<Fp16Section>& sections() {
    static const std::vector<Fp16Section> s = analyzeFp16();
    return s;
}

const Fp16Section& section(const std::string& prefix) {
    for (const Fp16Section& s : sections()) {
        if (s.title.rfind(prefix, 0) == 0) return s;
    }
    throw std::runtime_error("no fp16 section " + prefix);
}

std::string reportPath() {
    if (const char* path = std::getenv("CANDELA_FP16_REPORT")) return path;
    return CANDELA_FP16_REPORT_PATH;
}

}  // namespace

TEST(Fp16Report, WritesReportAndFindsKnownLimits) {
    const std::string path = reportPath();
    {
        std::ofstream out(path);
        ASSERT_TRUE(out) << "cannot write " << path;
        out << fp16Markdown(sections());
    }
    std::printf("fp16 report written to %s\n", path.c_str());
    for (const Fp16Section& s : sections()) {
        for (const std::string& f : s.findings)
            std::printf("  %s\n", f.c_str());
    }
    std::ifstream back(path);
    std::string firstLine;
    std::getline(back, firstLine);
    EXPECT_EQ(firstLine, "# fp16 (mediump) report for the shared shading terms");
}

// At NoH = 1, d = (a2 - 1) + 1 in half: a2 - 1 rounds to -1 when a2 <= 2^-12 (ties to even),
// i.e. roughness <= 0.125 (alpha = 1/64), and D = a2 / 0.
TEST(Fp16Report, GgxOverflowsExactlyWhereA2MinusOneRoundsToMinusOne) {
    for (const Fp16Row& r : section("distributionGgx").rows) {
        EXPECT_EQ(r.overflows, r.parameter <= 0.125) << "roughness " << r.label;
        if (r.overflows) {
            EXPECT_GT(r.firstOverflowAt, 0.999) << "roughness " << r.label;
        }
        // d is quantised to 2^-11 near the peak: > 1% off for every roughness below 0.5.
        if (r.parameter < 0.5) {
            EXPECT_TRUE(r.exceeds) << "roughness " << r.label;
        }
    }
    EXPECT_LT(section("distributionGgx").rows.back().worstError, 1e-2);  // roughness 1: D = 1/pi
}

// 0.25 / k^2 > 65504 for k = alpha / 2 < 1.95e-3: roughness <= 0.0625 (k = 2^-9 gives 65536).
TEST(Fp16Report, SchlickVisibilityOverflowsBelowRoughness0625) {
    for (const Fp16Row& r : section("visibilitySmithSchlick").rows) {
        EXPECT_EQ(r.overflows, r.parameter <= 0.0625) << "roughness " << r.label;
    }
}

// The 1e-12 floor is 0 in half: NoV = NoL = 0 divides by zero at every roughness.
TEST(Fp16Report, CorrelatedVisibilityOverflowsAtGrazingForAllRoughness) {
    for (const Fp16Row& r : section("visibilitySmithGgxCorrelated").rows) {
        EXPECT_TRUE(r.overflows) << "roughness " << r.label;
        EXPECT_EQ(r.firstOverflowAt, 0.0) << "roughness " << r.label;
    }
}

// Bounded terms stay finite in half.
TEST(Fp16Report, FresnelAndEnvBrdfStayFinite) {
    for (const char* name : {"fresnelSchlickSg", "envBrdfApprox"}) {
        for (const Fp16Row& r : section(name).rows) {
            EXPECT_FALSE(r.overflows) << name << " " << r.label;
        }
    }
}

// d^2 overflows half past 255.9 m (d^2 > 65504), so the falloff is 1 / Inf = 0 from the first
// scanned distance beyond it (281.8 m on the 20-per-decade grid), while the exact value
// (~1.3e-5) is still a half subnormal.
TEST(Fp16Report, FalloffFlushesToZeroPast256Metres) {
    for (const Fp16Row& r : section("falloff").rows) {
        if (r.parameter < 300.0) {
            EXPECT_FALSE(r.underflows) << "radius " << r.label;
            continue;
        }
        EXPECT_TRUE(r.underflows) << "radius " << r.label;
        EXPECT_GT(r.firstUnderflowAt, 255.9) << "radius " << r.label;
        EXPECT_LE(r.firstUnderflowAt, 300.0) << "radius " << r.label;
    }
}
