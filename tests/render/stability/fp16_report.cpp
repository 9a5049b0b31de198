#include "fp16_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>

#include "brdf_reference.h"
#include "fp16_shading.h"
#include "half_float.h"
#include "light_reference.h"

namespace candela::stability {

namespace ref = reference;
namespace emu = emulated;

namespace {

constexpr double kErrorLimit = 1e-2;

struct Evaluation {
    double reference;
    float half;
};

std::string format(double v) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.4g", v);
    return text;
}

// Collapses the flagged points of a sweep into "[a, b]" intervals (at most a few).
std::string ranges(const std::vector<double>& xs, const std::vector<bool>& flagged) {
    std::ostringstream out;
    int intervals = 0;
    for (size_t i = 0; i < xs.size();) {
        if (!flagged[i]) {
            ++i;
            continue;
        }
        size_t j = i;
        while (j + 1 < xs.size() && flagged[j + 1])
            ++j;
        if (intervals == 3) {
            out << ", ...";
            break;
        }
        if (intervals++ > 0) out << ", ";
        if (i == j) {
            out << format(xs[i]);
        } else {
            out << "[" << format(xs[i]) << ", " << format(xs[j]) << "]";
        }
        i = j + 1;
    }
    return intervals == 0 ? "-" : out.str();
}

// `relativeFloor`: errors are |half - ref| / max(|ref|, relativeFloor), so values below the
// floor are compared absolutely (0 = purely relative).
Fp16Row scan(const std::string& label, double parameter, const std::vector<double>& xs,
             const std::function<Evaluation(double)>& evaluate, double relativeFloor) {
    Fp16Row row;
    row.label = label;
    row.parameter = parameter;
    std::vector<bool> overflow(xs.size()), underflow(xs.size()), exceeds(xs.size());
    for (size_t i = 0; i < xs.size(); ++i) {
        const Evaluation e = evaluate(xs[i]);
        const double magnitude = std::fabs(e.reference);
        if (!std::isfinite(e.half)) {
            overflow[i] = true;
        } else {
            // Underflow: a result the half range should hold as a normal number comes out
            // subnormal or zero (precision gone), or a non-zero one comes out zero.
            underflow[i] = (magnitude >= kHalfMinNormal && std::fabs(e.half) < kHalfMinNormal) ||
                           (magnitude > 0.0 && e.half == 0.0f);
            const double error =
                std::fabs(double(e.half) - e.reference) / std::max(magnitude, relativeFloor);
            if (magnitude > 0.0 || relativeFloor > 0.0) {
                if (error > row.worstError) {
                    row.worstError = error;
                    row.worstAt = xs[i];
                }
                exceeds[i] = error > kErrorLimit;
            }
        }
        if (overflow[i]) exceeds[i] = true;
    }
    for (size_t i = xs.size(); i-- > 0;) {
        if (overflow[i]) row.firstOverflowAt = xs[i];
        if (underflow[i]) row.firstUnderflowAt = xs[i];
    }
    row.overflows = std::find(overflow.begin(), overflow.end(), true) != overflow.end();
    row.underflows = std::find(underflow.begin(), underflow.end(), true) != underflow.end();
    row.exceeds = std::find(exceeds.begin(), exceeds.end(), true) != exceeds.end();
    row.errorRanges = ranges(xs, exceeds);
    row.overflowRanges = ranges(xs, overflow);
    row.underflowRanges = ranges(xs, underflow);
    return row;
}

// Cosines from 0 to 1 with most points close to 1, where narrow lobes live.
std::vector<double> cosinesTowardOne() {
    std::vector<double> xs;
    for (int i = 0; i <= 20; ++i)
        xs.push_back(i / 20.0);
    for (int k = 27; k <= 140; ++k)
        xs.push_back(1.0 - std::pow(10.0, -k / 20.0));
    xs.push_back(1.0);
    std::sort(xs.begin(), xs.end());
    xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
    return xs;
}

std::vector<double> cosinesFromZero() {
    std::vector<double> xs = {0.0};
    for (int k = 140; k >= 0; --k)
        xs.push_back(std::pow(10.0, -k / 20.0));  // 1e-7 .. 1
    return xs;
}

std::vector<double> uniform(int count) {
    std::vector<double> xs;
    for (int i = 0; i <= count; ++i)
        xs.push_back(double(i) / count);
    return xs;
}

const std::vector<double> kRoughnessRows = {0.02, 0.03, 0.05, 0.0625, 0.07, 0.1, 0.12, 0.125,
                                            0.13, 0.15, 0.2,  0.3,    0.4,  0.5, 0.7,  1.0};

// The largest row parameter whose row has the flag, or -1.
double largest(const Fp16Section& s, bool Fp16Row::*flag) {
    double found = -1.0;
    for (const Fp16Row& r : s.rows) {
        if (r.*flag) found = std::max(found, r.parameter);
    }
    return found;
}

Fp16Section distributionSection() {
    Fp16Section s{"distributionGgx (eq. 3)",
                  "D(a2, NoH) with alpha = alphaFromRoughness(roughness), a2 = alpha^2, every "
                  "operation in half; relative error against the double reference at the exact "
                  "inputs (so rounding NoH to half is part of the error, as in a half shader).",
                  "roughness",
                  "NoH",
                  {},
                  {}};
    for (double roughness : kRoughnessRows) {
        s.rows.push_back(scan(
            format(roughness), roughness, cosinesTowardOne(),
            [&](double NoH) {
                const Half alpha = emu::alphaFromRoughness(Half(float(roughness)));
                return Evaluation{ref::ggxDistribution(ref::alphaFromRoughness(roughness), NoH),
                                  float(emu::distributionGgx(alpha * alpha, Half(float(NoH))))};
            },
            0.0));
    }
    return s;
}

Fp16Section visibilitySection(bool correlated) {
    Fp16Section s{correlated ? "visibilitySmithGgxCorrelated" : "visibilitySmithSchlick (eq. 4)",
                  "Vis(alpha, NoV, NoL) on the diagonal NoV = NoL (the worst case: both small), "
                  "every operation in half; relative error against the double reference.",
                  "roughness",
                  "NoV = NoL",
                  {},
                  {}};
    for (double roughness : kRoughnessRows) {
        s.rows.push_back(scan(
            format(roughness), roughness, cosinesFromZero(),
            [&](double c) {
                const double alpha = ref::alphaFromRoughness(roughness);
                const Half a = emu::alphaFromRoughness(Half(float(roughness)));
                const Half h{float(c)};
                if (correlated) {
                    // At NoV = NoL = 0 the exact value diverges; fp32's 1e-12 floor is the
                    // shader's own limit, so that is the reference there.
                    const double v =
                        c > 0.0 ? ref::smithGgxCorrelatedVisibility(alpha, c, c) : 0.5 / 1e-12;
                    return Evaluation{v, float(emu::visibilitySmithGgxCorrelated(a, h, h))};
                }
                const double k = alpha / 2.0;
                const double g = c * (1.0 - k) + k;  // eq. 4 folded with 1 / (4 NoL NoV)
                const double v =
                    c > 0.0 ? ref::smithSchlickVisibility(alpha, c, c) : 0.25 / (g * g);
                return Evaluation{v, float(emu::visibilitySmithSchlick(a, h, h))};
            },
            0.0));
    }
    return s;
}

Fp16Section fresnelSection() {
    Fp16Section s{"fresnelSchlickSg (eq. 5)",
                  "F(F0, VoH) with the 2% shadowing rule, every operation in half; relative "
                  "error against the double reference.",
                  "F0",
                  "VoH",
                  {},
                  {}};
    for (double f0 : {0.02, 0.04, 0.1, 0.5, 0.9, 1.0}) {
        s.rows.push_back(scan(
            format(f0), f0, uniform(200),
            [&](double VoH) {
                const Half h0{float(f0)};
                return Evaluation{ref::fresnelSchlickSg(f0, f0, VoH),
                                  float(emu::fresnelSchlickSg(h0, h0, Half(float(VoH))))};
            },
            0.0));
    }
    return s;
}

Fp16Section envBrdfSection() {
    Fp16Section s{"envBrdfApprox (Karis 2014)",
                  "EnvBRDFApprox(F0 = 0.04, roughness, NoV), clamped at 0 as brdf.glsl does, "
                  "every operation in half (Karis 2014, \"Physically Based Shading on Mobile\", "
                  "declares it half); error relative to "
                  "max(|value|, 0.01): reflectances under 1% are compared absolutely.",
                  "roughness",
                  "NoV",
                  {},
                  {}};
    for (double roughness : kRoughnessRows) {
        s.rows.push_back(scan(
            format(roughness), roughness, uniform(200),
            [&](double NoV) {
                const double reference = std::max(ref::envBrdfApprox(0.04, roughness, NoV), 0.0);
                return Evaluation{reference,
                                  float(emu::envBrdfApprox(Half(0.04f), Half(float(roughness)),
                                                           Half(float(NoV))))};
            },
            1e-2));
    }
    return s;
}

Fp16Section falloffSection() {
    Fp16Section s{"falloff (eq. 9, metres)",
                  "attenuationWindow(d^2, 1/r) * inverseSquare(d^2) with d^2 formed in half "
                  "from d; relative error against the double reference.",
                  "attenuation radius (m)",
                  "distance (m)",
                  {},
                  {}};
    std::vector<double> distances;
    for (int k = -60; k <= 80; ++k)
        distances.push_back(std::pow(10.0, k / 20.0));  // 1 mm..10 km
    for (double radius : {1.0, 10.0, 100.0, 1000.0, 1e4}) {
        std::vector<double> inside;
        for (double d : distances) {
            if (d < radius) inside.push_back(d);
        }
        s.rows.push_back(scan(
            format(radius), radius, inside,
            [&](double d) {
                const Half hd{float(d)};
                const Half d2 = hd * hd;
                const float half = float(emu::attenuationWindow(d2, Half(float(1.0 / radius))) *
                                         emu::inverseSquare(d2));
                return Evaluation{ref::attenuationWindow(d, radius) * ref::inverseSquare(d), half};
            },
            0.0));
    }
    return s;
}

void summarize(Fp16Section& s, const char* what) {
    const double over = largest(s, &Fp16Row::overflows);
    const double under = largest(s, &Fp16Row::underflows);
    const double exceed = largest(s, &Fp16Row::exceeds);
    auto line = [&](const char* kind, double value) {
        if (value < 0.0) return std::string("no ") + kind + " anywhere in the scan";
        return std::string(kind) + " for " + s.parameter + " up to " + format(value);
    };
    s.findings.push_back(std::string(what) + ": " + line("Inf/NaN", over) + "; " +
                         line("underflow", under) + "; " + line("error > 1e-2", exceed) + ".");
}

}  // namespace

std::vector<Fp16Section> analyzeFp16() {
    std::vector<Fp16Section> sections;
    sections.push_back(distributionSection());
    summarize(sections.back(), "D");
    sections.back().findings.push_back(
        "Why: d = (NoH a2 - NoH) NoH + 1 is formed next to 1, where halves are 2^-11 apart; "
        "for a2 < 2^-12 (roughness < 0.125) a2 - 1 rounds to -1, d = 0 and D = a2 / 0 = Inf at "
        "the peak. Above that d is quantised in steps of ~4.9e-4, so D near the peak is off "
        "by > 1% until a2 is a few 1e-2. NoH itself is quantised to 4.9e-4 below 1. A half "
        "GGX needs 1 - NoH^2 from |N x H|^2 and roughness clamped well above 0.02.");
    sections.push_back(visibilitySection(false));
    summarize(sections.back(), "Vis (Schlick)");
    sections.back().findings.push_back(
        "Why: at NoV = NoL = 0 the result is 0.25 / k^2 with k = alpha / 2, which exceeds 65504 "
        "for k < 1.95e-3, i.e. roughness < 0.0625.");
    sections.push_back(visibilitySection(true));
    summarize(sections.back(), "Vis (correlated)");
    sections.back().findings.push_back(
        "Why: the 1e-12 floor of max(lambdaV + lambdaL, 1e-12) is 0 in half, so NoV = NoL = 0 "
        "gives 0.5 / 0 = Inf at every roughness; and lambda ~ alpha * NoL underflows for small "
        "alpha and cosines.");
    sections.push_back(fresnelSection());
    summarize(sections.back(), "F");
    sections.push_back(envBrdfSection());
    summarize(sections.back(), "EnvBRDFApprox");
    sections.push_back(falloffSection());
    summarize(sections.back(), "falloff");
    sections.back().findings.push_back(
        "Why: d^2 overflows half beyond d = 255.9 m (d^2 > 65504), so the falloff becomes "
        "1 / Inf = 0; from d = 128 m on, 1 / d^2 is already a half subnormal (precision falls "
        "to ~0.4% by 256 m). The window's 1 - (d/r)^4 cancels near the attenuation radius, "
        "where the falloff is small anyway. "
        "Illuminance = candela * falloff also overflows close to a light: with the 1e-4 m^2 "
        "bias, falloff <= 1e4, so any source above 6.55 cd (82 lm) overflows half within "
        "sqrt(cd / 65504) m of it, and a light of more than 65504 cd (8.2e5 lm) overflows "
        "half by its intensity alone.");
    return sections;
}

std::string fp16Markdown(const std::vector<Fp16Section>& sections) {
    std::ostringstream md;
    md << "# fp16 (mediump) report for the shared shading terms\n\n"
       << "Generated by `render_stability_tests` (test "
          "`Fp16Report.WritesReportAndFindsKnownLimits`,"
       << " source `tests/render/stability/fp16_report.cpp`); every run rewrites it in the build "
          "folder and prints the path. A copy of one run is committed as "
          "`tests/render/stability/FP16_REPORT.md`.\n\n"
       << "Method: the functions of `render/shaders/common/brdf.glsl` and `lights.glsl` are "
          "transliterated operation by operation (`fp16_shading.h`, checked against the device "
          "in fp32) and run with every operation rounded to IEEE binary16 (`half_float.h`: round "
          "to nearest even, subnormals, overflow to Inf; exp2 and sqrt correctly rounded, which "
          "is kinder than most mediump hardware). Inputs are rounded to half too. Errors are "
          "against the double-precision reference (`brdf_reference.h`, `light_reference.h`). "
          "Flags: *Inf/NaN* = the half result is not finite; *underflow* = a result that is a "
          "normal half in exact arithmetic comes out subnormal or zero; *error > 1e-2* includes "
          "the Inf/NaN points. Ranges list the swept input's grid points that are flagged.\n\n"
       << "## Summary\n\n";
    for (const Fp16Section& s : sections) {
        for (const std::string& f : s.findings)
            md << "- " << f << "\n";
    }
    for (const Fp16Section& s : sections) {
        md << "\n## " << s.title << "\n\n"
           << s.formula << "\n\n"
           << "| " << s.parameter << " | worst error | at " << s.swept << " | " << s.swept
           << " with error > 1e-2 | " << s.swept << " with Inf/NaN | " << s.swept
           << " with underflow |\n"
           << "|---|---|---|---|---|---|\n";
        for (const Fp16Row& r : s.rows) {
            md << "| " << r.label << " | " << format(r.worstError) << " | " << format(r.worstAt)
               << " | " << r.errorRanges << " | " << r.overflowRanges << " | " << r.underflowRanges
               << " |\n";
        }
    }
    return md.str();
}

}  // namespace candela::stability
