// candela-report: the speed-against-error table of the renderer's approximations (issue 8),
// each approximation's error against a reference and its cost against the reference's,
// measured in this run on this machine. scripts/report regenerates docs/speed-vs-error.md.
//
//   build/bin/candela-report [--out FILE] [--quick] [--section NAME]
//
// --section: only the sections whose name contains NAME (checking one section without
// running the others).
// --quick: coarse grids and one repetition (the ctest smoke test); the numbers are then only
// good for checking that every row is produced.
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

#include "../stability/compute_harness.h"
#include "ibl/environment_brdf_lut.h"
#include "report_context.h"
#include "svg_figures.h"

using namespace candela;
using namespace candela::report;

namespace {

// The LUT as the renderer computes it, its Schlick-Smith pair (eq. 4, the UE4 BRDF) unpacked
// from 16-bit UNORM to (scale, bias).
std::vector<float> environmentBrdfLut(render::GpuContext& context) {
    render::EnvironmentBrdfLut lut(context);
    const uint32_t n = render::EnvironmentBrdfLut::kSize;
    std::vector<float> values(size_t(n) * n * 2);
    for (size_t i = 0; i < size_t(n) * n; ++i) {
        const uint32_t packed = lut.packedSchlick(uint32_t(i));
        values[2 * i] = float((packed & 0xFFFFu) / 65535.0);
        values[2 * i + 1] = float((packed >> 16) / 65535.0);
    }
    return values;
}

// Error against cost, log-log, one point per row that has both (ReportRow::costNs).
ReportFigure errorAgainstCostFigure(const Report& report) {
    LogLogPlot plot;
    plot.title = "Error against cost, one point per approximation";
    plot.xAxis = "cost: device ns per evaluation (this run's device)";
    plot.yAxis = "error (the row's own metric and unit)";
    for (const ReportRow& row : report.rows) {
        if (row.costNs > 0.0 && row.error > 0.0) {
            plot.points.push_back(
                {row.approximation + " (" + row.errorUnit + ")", row.costNs, row.error});
        }
    }
    return {"speed-vs-error-frontier.svg",
            "Error against cost for every row with a per-evaluation cost (log-log): lower left is "
            "better; rows timed per frame or under the timer's noise are not plotted.",
            logLogScatterSvg(plot)};
}

// Writes `text` to `path` through a temporary file renamed into place; throws naming the path
// and the OS error.
void writeAtomically(const std::filesystem::path& path, const std::string& text) {
    const std::filesystem::path temporary = path.string() + ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary);
        out << text;
        out.flush();
        if (!out) {
            throw std::runtime_error("cannot write " + temporary.string() + ": " +
                                     std::generic_category().message(errno));
        }
    }
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) {
        throw std::runtime_error("cannot rename " + temporary.string() + " to " + path.string() +
                                 ": " + error.message());
    }
}

int usage() {
    std::fprintf(stderr, "usage: candela-report [--out FILE] [--quick] [--section NAME]\n");
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    std::string outPath;
    std::string only;
    Budget budget;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--quick")) {
            budget.quick = true;
        } else if (!std::strcmp(argv[i], "--out") && i + 1 < argc) {
            outPath = argv[++i];
        } else if (!std::strcmp(argv[i], "--section") && i + 1 < argc) {
            only = argv[++i];
        } else {
            return usage();
        }
    }
    try {
        const auto start = std::chrono::steady_clock::now();
        stability::ComputeHarness harness;
        const std::vector<float> lut = environmentBrdfLut(harness.context());
        ShaderCost cost(harness, lut, render::EnvironmentBrdfLut::kSize, budget.quick ? 3 : 11,
                        budget.quick ? 4096 : 16384);
        Report report;
        report.device = harness.context().deviceName();
        report.budget =
            budget.quick ? "quick (smoke test: coarse grids, numbers not meaningful)" : "full";
        ReportContext context{harness, cost, budget, report};
        auto section = [&](const char* name, auto&& run) {
            if (std::string(name).find(only) == std::string::npos) return;
            std::fprintf(stderr, "candela-report: %s\n", name);
            run();
        };
        section("BRDF terms", [&] { addBrdfRows(context); });
        section("environment BRDF",
                [&] { addEnvironmentBrdfRows(context, lut, render::EnvironmentBrdfLut::kSize); });
        section("area lights", [&] { addAreaLightRows(context); });
        section("area lights by LTC", [&] { addLtcAreaLightRows(context); });
        section("area light shapes", [&] { addAreaLightShapeRows(context); });
        section("falloff", [&] { addFalloffRow(context); });
        section("image-based lighting", [&] { addSplitSumRow(context); });
        section("clustered lights", [&] { addClusteredRow(context); });
        section("energy-conserving BRDF", [&] { addBrdfEnergyRows(context); });
        section("antialiasing", [&] {
            addAntialiasingRows(context);
            addForwardMsaaRows(context);
        });
        section("material extensions", [&] { addMaterialRows(context); });
        section("ambient occlusion", [&] { addAmbientOcclusionRows(context); });
        section("sky occlusion", [&] { addSkyOcclusionRows(context); });
        section("shadows", [&] { addShadowRows(context); });
        section("animation", [&] { addAnimationRows(context); });
        section("screen-space reflections", [&] { addSsrRows(context); });
        section("volumetrics", [&] { addVolumetricsRows(context); });
        section("atmosphere", [&] { addAtmosphereRows(context); });
        section("light shafts", [&] { addScatteringRows(context); });
        section("wires", [&] { addWireRows(context); });
        section("hair", [&] { addHairRows(context); });
        section("levels of detail", [&] { addLevelOfDetailRows(context); });
        if (harness.validationMessages() != 0) {
            std::fprintf(stderr, "candela-report: %u Vulkan validation messages\n",
                         harness.validationMessages());
            return 1;
        }
        report.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (!report.figures.empty() || !report.rows.empty()) {
            report.figures.insert(report.figures.begin(), errorAgainstCostFigure(report));
        }
        // Figures go beside the page (with no --out, nowhere: the page alone goes to stdout).
        if (!outPath.empty()) {
            const std::filesystem::path folder = std::filesystem::path(outPath).parent_path();
            for (const ReportFigure& figure : report.figures)
                writeAtomically(folder / figure.file, figure.svg);
        }
        const std::string markdown = toMarkdown(report);
        if (outPath.empty()) {
            std::fputs(markdown.c_str(), stdout);
        } else {
            std::ofstream out(outPath, std::ios::binary);
            out << markdown;
            if (!out) {
                std::fprintf(stderr, "candela-report: cannot write %s\n", outPath.c_str());
                return 1;
            }
        }
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "candela-report: %s\n", e.what());
        return 1;
    }
}
