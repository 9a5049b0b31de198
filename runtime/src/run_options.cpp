#include "run_options.h"

#include "candela/runtime/application.h"

#include <charconv>
#include <cstdlib>

namespace candela::runtime {

namespace {

constexpr uint32_t kMaxDimension = 16384;

bool parseUint(const std::string& text, uint32_t& value) {
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, value);
    return ec == std::errc() && ptr == end;
}

// "WxH" with both sides in 1..16384.
bool parseSize(const std::string& text, uint32_t& width, uint32_t& height) {
    size_t x = text.find('x');
    if (x == std::string::npos) return false;
    return parseUint(text.substr(0, x), width) && parseUint(text.substr(x + 1), height) &&
           width > 0 && height > 0 && width <= kMaxDimension && height <= kMaxDimension;
}

bool parseSeconds(const std::string& text, double& value) {
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, value);
    return ec == std::errc() && ptr == end && value >= 0.001 && value <= 60.0;
}

}  // namespace

std::string runUsage() {
    return "usage: candela run <scene.json|scene.gltf|scene.glb|builtin:triangle> [--headless]\n"
           "                   [--size WxH] [--frames N] [--capture FILE.exr|FILE.png]...\n"
           "                   [--stats FILE.json] [--lights clustered|brute-force]\n"
           "                   [--light-assign auto|cpu|gpu] [--validation off|on|require]\n"
           "                   [--step SECONDS] [--capture-each DIR] [--summary FILE.md]\n"
           "                   [--input SCRIPT] [--overlay|--no-overlay]\n"
           "                   [--validation off|on|require] [--step SECONDS]\n"
           "                   [--capture-each DIR] [--summary FILE.md] [--input SCRIPT]\n"
           "                   [--overlay|--no-overlay]\n"
           "                   [--env SKY.exr] [--ibl split-sum|mobile|reference]\n"
           "                   [--brdf ue4|energy-conserving]\n"
           "       candela demo [same options]\n";
}

ParseResult parseRunOptions(const std::vector<std::string>& args) {
    ParseResult result;
    RunOptions options;
    options.validation = validationModeFromEnvironment();
    auto fail = [&](std::string message) {
        result.error = std::move(message);
        return result;
    };
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        auto value = [&](std::string& out) {
            if (i + 1 >= args.size()) return false;
            out = args[++i];
            return true;
        };
        std::string v;
        if (arg == "--help" || arg == "-h") {
            result.helpRequested = true;
            return result;
        } else if (arg == "--headless") {
            options.headless = true;
        } else if (arg == "--size") {
            if (!value(v) || !parseSize(v, options.width, options.height)) {
                return fail("--size needs WxH with both sides between 1 and 16384, got '" + v +
                            "'");
            }
        } else if (arg == "--frames") {
            if (!value(v) || !parseUint(v, options.frames) || options.frames == 0) {
                return fail("--frames needs a positive integer, got '" + v + "'");
            }
        } else if (arg == "--capture") {
            if (!value(v)) return fail("--capture needs a file name ending in .exr or .png");
            options.captures.push_back(v);
        } else if (arg == "--frame-graph") {
            if (!value(v)) return fail("--frame-graph needs a file name (FILE.dot)");
            options.frameGraph = v;
        } else if (arg == "--stats") {
            if (!value(v)) return fail("--stats needs a file name");
            options.stats = v;
        } else if (arg == "--lights") {
            if (!value(v)) return fail("--lights needs clustered or brute-force");
            if (v == "clustered")
                options.lightCulling = render::LightCulling::Clustered;
            else if (v == "brute-force")
                options.lightCulling = render::LightCulling::BruteForce;
            else
                return fail("--lights needs clustered or brute-force, got '" + v + "'");
        } else if (arg == "--light-assign") {
            if (!value(v)) return fail("--light-assign needs auto, cpu or gpu");
            if (v == "auto")
                options.lightAssignment = render::LightAssignmentDevice::Auto;
            else if (v == "cpu")
                options.lightAssignment = render::LightAssignmentDevice::Cpu;
            else if (v == "gpu")
                options.lightAssignment = render::LightAssignmentDevice::Gpu;
            else
                return fail("--light-assign needs auto, cpu or gpu, got '" + v + "'");
        } else if (arg == "--validation") {
            if (!value(v)) return fail("--validation needs off, on or require");
            if (v == "off")
                options.validation = render::ValidationMode::Off;
            else if (v == "on")
                options.validation = render::ValidationMode::IfPresent;
            else if (v == "require")
                options.validation = render::ValidationMode::Required;
            else
                return fail("--validation needs off, on or require, got '" + v + "'");
        } else if (arg == "--step") {
            double step = 0.0;
            if (!value(v) || !parseSeconds(v, step)) {
                return fail(
                    "--step needs seconds per frame, a number between 0.001 and 60, "
                    "got '" +
                    v + "'");
            }
            options.stepSeconds = step;
        } else if (arg == "--overlay") {
            options.overlay = true;
        } else if (arg == "--no-overlay") {
            options.overlay = false;
        } else if (arg == "--capture-each") {
            if (!value(v)) return fail("--capture-each needs a directory");
            options.captureEach = v;
        } else if (arg == "--summary") {
            if (!value(v)) return fail("--summary needs a file name");
            options.summary = v;
        } else if (arg == "--input") {
            if (!value(v)) return fail("--input needs an input script (see input_script.h)");
            options.inputScript = v;
        } else if (arg == "--env") {
            if (!value(v)) return fail("--env needs an OpenEXR file");
            options.environment = v;
        } else if (arg == "--ibl") {
            if (!value(v)) return fail("--ibl needs split-sum, mobile or reference");
            if (v == "split-sum")
                options.ibl = render::IblMode::SplitSum;
            else if (v == "mobile")
                options.ibl = render::IblMode::Mobile;
            else if (v == "reference")
                options.ibl = render::IblMode::Reference;
            else
                return fail("--ibl needs split-sum, mobile or reference, got '" + v + "'");
        } else if (arg == "--brdf") {
            if (!value(v)) return fail("--brdf needs ue4 or energy-conserving");
            if (v == "ue4")
                options.brdf = render::BrdfModel::Ue4;
            else if (v == "energy-conserving")
                options.brdf = render::BrdfModel::EnergyConserving;
            else
                return fail("--brdf needs ue4 or energy-conserving, got '" + v + "'");
        } else if (!arg.empty() && arg[0] == '-') {
            return fail("unknown option '" + arg + "'");
        } else if (options.scene.empty()) {
            options.scene = arg;
        } else {
            return fail("more than one scene given: '" + options.scene + "' and '" + arg + "'");
        }
    }
    for (const std::filesystem::path& capture : options.captures) {
        std::string ext = capture.extension().string();
        if (ext != ".exr" && ext != ".png") {
            return fail("--capture file must end in .exr or .png: '" + capture.string() + "'");
        }
    }
    result.options = options;
    return result;
}

}  // namespace candela::runtime
