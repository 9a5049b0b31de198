#pragma once
// Where the shared shading terms break in half precision (Karis 2014's ("Physically Based Shading
// on Mobile") mobile shaders compute in `half`): each term is run with every operation rounded to
// binary16 (fp16_shading.h over Half) and compared with the double reference over a grid of inputs.
// The findings become FP16_REPORT.md.
#include <string>
#include <vector>

namespace candela::stability {

// One row of a scan: a fixed parameter (e.g. roughness) and the swept input (e.g. NoH).
struct Fp16Row {
    std::string label;            // the fixed parameter, as printed
    double parameter = 0.0;       // its value
    double worstError = 0.0;      // largest error (relative unless the section says otherwise)
    double worstAt = 0.0;         // swept input of the worst error
    std::string errorRanges;      // swept inputs whose error exceeds 1e-2
    std::string overflowRanges;   // ... that give Inf or NaN
    std::string underflowRanges;  // ... whose result leaves the normal half range or becomes 0
    bool overflows = false;
    bool underflows = false;
    bool exceeds = false;
    double firstOverflowAt = -1.0;  // smallest flagged swept input, -1 when none
    double firstUnderflowAt = -1.0;
};

struct Fp16Section {
    std::string title;
    std::string formula;    // what was emulated, and how errors are measured
    std::string parameter;  // column header of the row parameter
    std::string swept;      // name of the swept input
    std::vector<Fp16Row> rows;
    std::vector<std::string> findings;  // summary lines
};

std::vector<Fp16Section> analyzeFp16();
std::string fp16Markdown(const std::vector<Fp16Section>& sections);

}  // namespace candela::stability
