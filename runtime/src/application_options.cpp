#include "candela/runtime/application_options.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "candela/content/component_validation.h"
#include "candela/content/render_setting_table.h"
#include "candela/runtime/exit_code.h"

namespace candela::runtime {

namespace {

constexpr std::uint32_t kMaxDimension = 16384;

bool parseUint(const std::string& text, std::uint32_t& value) {
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, value);
    return ec == std::errc() && ptr == end;
}

// "WxH" with both sides in 1..16384.
bool parseSize(const std::string& text, std::uint32_t& width, std::uint32_t& height) {
    size_t x = text.find('x');
    if (x == std::string::npos) return false;
    return parseUint(text.substr(0, x), width) && parseUint(text.substr(x + 1), height) &&
           width > 0 && height > 0 && width <= kMaxDimension && height <= kMaxDimension;
}

bool parseFloat(const std::string& text, float& value) {
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, value);
    return ec == std::errc() && ptr == end && std::isfinite(value);
}

bool parseSeconds(const std::string& text, double& value) {
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, value);
    return ec == std::errc() && ptr == end && value >= 0.001 && value <= 60.0;
}

// One of `names` (spelled as on the command line) to its enum value.
template <typename Enum, size_t N>
bool parseChoice(const std::string& text, const std::pair<const char*, Enum> (&names)[N],
                 Enum& value) {
    for (const auto& [name, choice] : names) {
        if (text == name) {
            value = choice;
            return true;
        }
    }
    return false;
}

constexpr std::pair<const char*, render::LightCulling> kCullings[] = {
    {"clustered", render::LightCulling::Clustered},
    {"brute-force", render::LightCulling::BruteForce}};
constexpr std::pair<const char*, render::LightAssignmentDevice> kAssignments[] = {
    {"auto", render::LightAssignmentDevice::Auto},
    {"cpu", render::LightAssignmentDevice::Cpu},
    {"gpu", render::LightAssignmentDevice::Gpu}};
constexpr std::pair<const char*, render::ValidationMode> kValidations[] = {
    {"off", render::ValidationMode::Off},
    {"on", render::ValidationMode::IfPresent},
    {"require", render::ValidationMode::Required}};
constexpr std::pair<const char*, render::IblMode> kIbls[] = {
    {"split-sum", render::IblMode::SplitSum},
    {"mobile", render::IblMode::Mobile},
    {"reference", render::IblMode::Reference}};

// SIGMA_S[,SIGMA_A[,G]]: 1, 2 or 3 numbers by the Fog component's rules (validateFog); an
// empty string when they hold, else what is wrong.
// `clamps` gets "FIELD MESSAGE" for each value the fog rules clamped (component_validation.h).
std::string parseFog(const std::string& text, content::Fog& fog, std::vector<std::string>& clamps) {
    float values[3] = {0.0f, 0.0f, 0.0f};
    size_t count = 0;
    const char* at = text.data();
    const char* end = text.data() + text.size();
    while (true) {
        if (count == 3) return "at most three numbers (SIGMA_S,SIGMA_A,G)";
        auto [ptr, ec] = std::from_chars(at, end, values[count]);
        if (ec != std::errc()) return "'" + text + "' is not a list of numbers";
        ++count;
        if (ptr == end) break;
        if (*ptr != ',') return "'" + text + "' is not a comma-separated list of numbers";
        at = ptr + 1;
    }
    fog = content::Fog{};
    fog.scattering = values[0];
    fog.absorption = values[1];
    fog.anisotropy = values[2];
    for (const content::ValueProblem& problem : content::validateFog(fog)) {
        if (!problem.clamped) return problem.field + " " + problem.message;
        clamps.push_back(problem.field + " " + problem.message);
    }
    return {};
}

// When `arg` is a render setting's flag (content/render_setting_table.h): reads its value with
// `next` into `choices` and returns "" when the row allows it, else the problem. Nothing when
// `arg` is no setting's flag.
template <typename NextValue>
std::optional<std::string> renderSettingFlag(const std::string& arg, NextValue&& next,
                                             content::RenderSettingChoices& choices) {
    std::optional<std::string> result;
    content::forEachRenderSetting([&](const auto& row) {
        if (result || arg != row.flag) return;
        std::string text;
        const auto value = next(text) ? content::parseRenderSetting(row, text) : std::nullopt;
        if (!value) {
            result = arg + " needs " + content::renderSettingExpects(row) + ", got '" + text + "'";
            return;
        }
        choices.*row.choice = *value;
        result = std::string();
    });
    return result;
}

// A row's value in each quality preset: "default X" when the presets agree.
template <typename T>
std::string presetValuesText(const content::RenderSettingRow<T>& row) {
    bool same = true;
    for (const T& value : row.presets)
        same = same && value == row.presets[0];
    if (same) return "default " + content::renderSettingText(row, row.presets[0]);
    std::string values;
    for (const T& value : row.presets)
        values += (values.empty() ? "" : "/") + content::renderSettingText(row, value);
    return "low/medium/high/ultra: " + values;
}

// A usage line per render setting: its flag and values, what it does and its preset values
// (unless its help names its own default).
std::string renderSettingsUsage() {
    constexpr std::size_t kHelpColumn = 28;
    std::string usage;
    content::forEachRenderSetting([&](const auto& row) {
        std::string line =
            "  " + std::string(row.flag) + " " + content::renderSettingNames(row, "|");
        if (line.size() < kHelpColumn) {
            line.resize(kHelpColumn, ' ');
        } else {
            line += "\n" + std::string(kHelpColumn, ' ');
        }
        line += row.help;
        if (row.help.find("default") == std::string_view::npos)
            line += " (" + presetValuesText(row) + ")";
        usage += line + "\n";
    });
    return usage;
}

}  // namespace

std::string ApplicationOptions::standardFlagsUsage() {
    return "  --headless                render without a window (also when there is no display)\n"
           "  --size WxH                image size (default 1280x720)\n"
           "  --frames N                stop after N frames (headless default: 1)\n"
           "  --input SCRIPT            replay recorded input (see input_script.h)\n"
           "  --capture FILE.png|.exr   write the last frame (may repeat)\n"
           "  --audio-capture FILE.wav  write what a player hears (headless, 48 kHz stereo)\n"
           "  --record-input FILE       write the session's input as a script --input replays\n"
           "  --stats FILE.json         write per-run measurements\n"
           "  --stats-work every|last   frames whose lighting work --stats counts (default\n"
           "                            every; last: the others timed without counting)\n"
           "  --step SECONDS            scene time per frame when headless (default 1/30)\n"
           "  --validation off|on|require\n"
           "  --lights clustered|brute-force\n"
           "  --light-assign auto|cpu|gpu\n"
           "  --frame-graph FILE.dot    write the last frame's graph as Graphviz\n"
           "  --env SKY.exr             light the scene with this sky\n"
           "  --ibl split-sum|mobile|reference\n"
           "  --quality low|medium|high|ultra   every technique's settings in one preset\n"
           "                            (default: the scene file's, else medium on a CPU\n"
           "                            device, high on a GPU; a flag below wins over it)\n"
           "  render settings: each flag wins over the scene file's key of the same name,\n"
           "  which wins over the quality preset's value\n" +
           renderSettingsUsage() +
           "  --culling on|off          frustum culling of draws (off: the reference)\n"
           "  --physics-debug           draw every collider and contact point as wires\n"
           "  --fog SIGMA_S[,SIGMA_A[,G]]   a uniform medium (1/m, Henyey-Greenstein g),\n"
           "                            replacing the scene's fog\n"
           "  --atmosphere              a physically based sky (Earth's) instead of the EXR sky\n"
           "  --atmosphere off          no atmosphere, even where the scene has one\n"
           "  --sun-elevation DEG       the atmosphere's sun this high, keeping its azimuth\n"
           "  --time-of-day HH:MM       the atmosphere's sun where it stands then (solar time)\n"
           "  --scattering-initial-step N   every N-th sample marched first (default 16)\n"
           "  --scattering-threshold X  relative change that refines an interval (default 0.2)\n"
           "  --scattering-density X    the air's density for the shafts, times Earth's at the\n"
           "                            camera's altitude (default 50: haze)\n";
}

CommandLine parseCommandLine(const std::vector<std::string>& args, OtherArguments others,
                             ApplicationOptions defaults) {
    CommandLine result;
    ApplicationOptions options = std::move(defaults);
    auto fail = [&](std::string message) {
        result.error = std::move(message);
        result.exitCode = kExitBadArguments;
        return result;
    };
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        std::string v;
        auto value = [&]() {
            if (i + 1 >= args.size()) return false;
            v = args[++i];
            return true;
        };
        auto nextValue = [&](std::string& text) {
            if (!value()) return false;
            text = v;
            return true;
        };
        if (arg == "--help" || arg == "-h") {
            result.helpRequested = true;
            result.exitCode = kExitOk;
            return result;
        } else if (arg == "--headless") {
            options.headless = true;
        } else if (arg == "--size") {
            if (!value() || !parseSize(v, options.width, options.height)) {
                return fail("--size needs WxH with both sides between 1 and 16384, got '" + v +
                            "'");
            }
        } else if (arg == "--frames") {
            if (!value() || !parseUint(v, options.frames) || options.frames == 0) {
                return fail("--frames needs a positive integer, got '" + v + "'");
            }
        } else if (arg == "--capture") {
            if (!value()) return fail("--capture needs a file name ending in .exr or .png");
            std::string ext = std::filesystem::path(v).extension().string();
            if (ext != ".exr" && ext != ".png") {
                return fail("--capture file must end in .exr or .png: '" + v + "'");
            }
            options.captures.push_back({FrameCapture::kLastFrame, v});
        } else if (arg == "--record-input") {
            if (!value()) return fail("--record-input needs a file name");
            options.recordInput = v;
        } else if (arg == "--audio-capture") {
            if (!value()) return fail("--audio-capture needs a file name ending in .wav");
            if (std::filesystem::path(v).extension() != ".wav") {
                return fail("--audio-capture file must end in .wav: '" + v + "'");
            }
            options.audioCapture = v;
        } else if (arg == "--stats") {
            if (!value()) return fail("--stats needs a file name");
            options.stats = v;
        } else if (arg == "--stats-work") {
            if (!value() || (v != "every" && v != "last")) {
                return fail("--stats-work needs every or last, got '" + v + "'");
            }
            options.countWorkOnLastFrame = v == "last";
        } else if (arg == "--input") {
            if (!value()) return fail("--input needs an input script (see input_script.h)");
            std::string error;
            options.inputScript = InputScript::load(v, error);
            if (!options.inputScript) return fail(error);
        } else if (arg == "--step") {
            if (!value() || !parseSeconds(v, options.fixedStepSeconds)) {
                return fail("--step needs seconds per frame, a number between 0.001 and 60, got '" +
                            v + "'");
            }
        } else if (arg == "--frame-graph") {
            if (!value()) return fail("--frame-graph needs a file name (FILE.dot)");
            options.frameGraph = v;
        } else if (arg == "--lights") {
            if (!value() || !parseChoice(v, kCullings, options.lightCulling)) {
                return fail("--lights needs clustered or brute-force, got '" + v + "'");
            }
        } else if (arg == "--light-assign") {
            if (!value() || !parseChoice(v, kAssignments, options.lightAssignment)) {
                return fail("--light-assign needs auto, cpu or gpu, got '" + v + "'");
            }
        } else if (arg == "--validation") {
            if (!value() || !parseChoice(v, kValidations, options.validation)) {
                return fail("--validation needs off, on or require, got '" + v + "'");
            }
        } else if (arg == "--env") {
            if (!value()) return fail("--env needs an OpenEXR file");
            options.environment = v;
        } else if (arg == "--ibl") {
            if (!value() || !parseChoice(v, kIbls, options.ibl)) {
                return fail("--ibl needs split-sum, mobile or reference, got '" + v + "'");
            }
        } else if (arg == "--physics-debug") {
            options.physicsDebug = true;
        } else if (arg == "--culling") {
            if (!value() || (v != "on" && v != "off"))
                return fail("--culling needs on or off, got '" + v + "'");
            options.culling = v == "on";
        } else if (arg == "--quality") {
            const std::optional<content::QualityLevel> level =
                value() ? content::parseQualityLevel(v) : std::nullopt;
            if (!level) return fail("--quality needs low, medium, high or ultra, got '" + v + "'");
            options.quality = level;
        } else if (arg == "--fog") {
            if (!value()) return fail("--fog needs SIGMA_S[,SIGMA_A[,G]] (per metre)");
            content::Fog fog;
            std::vector<std::string> clamps;
            if (std::string problem = parseFog(v, fog, clamps); !problem.empty()) {
                return fail("--fog: " + problem);
            }
            for (const std::string& clamp : clamps)
                result.warnings.push_back("clamped: --fog " + clamp);
            options.fog = fog;
        } else if (arg == "--atmosphere") {
            // `--atmosphere off` drops the scene's atmosphere (tests that exercise something
            // else skip its passes); a bare --atmosphere adds one.
            if (i + 1 < args.size() && args[i + 1] == "off") {
                ++i;
                options.atmosphereOff = true;
            } else {
                options.atmosphere = true;
            }
        } else if (arg == "--scattering-initial-step") {
            if (!value() || !parseUint(v, options.scatteringSettings.initialStep) ||
                options.scatteringSettings.initialStep == 0 ||
                options.scatteringSettings.initialStep > 4096) {
                return fail(arg + " needs a count from 1 to 4096, got '" + v + "'");
            }
        } else if (arg == "--scattering-density") {
            float scale = 0.0f;
            if (!value() || !parseFloat(v, scale) || !(scale >= 0.0f) || scale > 1e6f) {
                return fail(
                    "--scattering-density needs a scale from 0 to 1e6 of the air's "
                    "density, got '" +
                    v + "'");
            }
            options.scatteringSettings.densityScale = scale;
        } else if (arg == "--scattering-threshold") {
            float threshold = 0.0f;
            if (!value() || !parseFloat(v, threshold) || !(threshold > 0.0f)) {
                return fail("--scattering-threshold needs a positive fraction, got '" + v + "'");
            }
            options.scatteringSettings.refinementThreshold = threshold;
        } else if (arg == "--sun-elevation") {
            float degrees = 0.0f;
            if (!value() || !parseFloat(v, degrees) || !(std::fabs(degrees) <= 90.0f)) {
                return fail("--sun-elevation needs degrees in [-90, 90], got '" + v + "'");
            }
            options.sunElevationDegrees = degrees;
        } else if (arg == "--time-of-day") {
            int hours = -1, minutes = -1;
            char tail = 0;
            // Hours are bounded before they are multiplied: 35791395:00 overflowed an int.
            if (!value() || std::sscanf(v.c_str(), "%d:%d%c", &hours, &minutes, &tail) != 2 ||
                hours < 0 || hours > 24 || minutes < 0 || minutes > 59 ||
                hours * 60 + minutes > 24 * 60) {
                return fail("--time-of-day needs HH:MM between 00:00 and 24:00, got '" + v + "'");
            }
            options.timeOfDayHours = float(hours) + float(minutes) / 60.0f;
        } else if (const std::optional<std::string> problem =
                       renderSettingFlag(arg, nextValue, options.settings)) {
            if (!problem->empty()) return fail(*problem);
        } else if (others == OtherArguments::Keep) {
            result.arguments.push_back(arg);
        } else if (!arg.empty() && arg[0] == '-') {
            return fail("unknown option '" + arg + "'");
        } else {
            return fail("unexpected argument '" + arg + "'");
        }
    }
    // A work estimate bounds the light shafts: each slice marches up to its samples, and 4096
    // x 4096 took 38 s for one 64x64 frame. 2^20 samples (8x ultra's 512 x 256) stay near a
    // second on lavapipe. The side not given is the largest any preset uses.
    const content::RenderSettingChoices& chosen = options.settings;
    if (chosen.scatteringSlices || chosen.scatteringSamples) {
        const std::uint64_t slices = chosen.scatteringSlices.value_or(512);
        const std::uint64_t samples = chosen.scatteringSamples.value_or(256);
        if (slices * samples > ApplicationOptions::kMaxScatteringSamples) {
            return fail("--scattering-slices " + std::to_string(slices) +
                        " x --scattering-samples " + std::to_string(samples) + " = " +
                        std::to_string(slices * samples) + " samples a frame, past the limit of " +
                        std::to_string(ApplicationOptions::kMaxScatteringSamples) +
                        " (8x the ultra preset's 512 x 256); lower one of them");
        }
    }
    result.options = std::move(options);
    return result;
}

CommandLine ApplicationOptions::fromCommandLine(int argc, const char* const* argv,
                                                OtherArguments others, std::string_view gameUsage) {
    std::vector<std::string> args;
    for (int i = 1; i < argc; ++i)
        args.emplace_back(argv[i]);
    const std::string program =
        argc > 0 ? std::filesystem::path(argv[0]).filename().string() : "game";
    ApplicationOptions defaults;
    defaults.validation = validationModeFromEnvironment();
    CommandLine result = parseCommandLine(args, others, std::move(defaults));
    for (const std::string& warning : result.warnings) {
        std::fprintf(stderr, "%s: warning: %s\n", program.c_str(), warning.c_str());
    }
    if (result.options) return result;
    std::string usage = "usage: " + program + " [options]";
    if (!gameUsage.empty()) usage += " " + std::string(gameUsage);
    usage += "\noptions:\n" + standardFlagsUsage();
    if (result.helpRequested) {
        std::fputs(usage.c_str(), stdout);
    } else {
        std::fprintf(stderr, "%s: %s\n%s", program.c_str(), result.error.c_str(), usage.c_str());
    }
    return result;
}

}  // namespace candela::runtime
