#include "candela/runtime/application_options.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "candela/content/component_validation.h"
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

bool parseFraction(const std::string& text, float& value) {
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, value);
    return ec == std::errc() && ptr == end && value >= 0.0f && value <= 1.0f;
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

constexpr std::pair<const char*, render::AntiAliasing> kAntiAliasing[] = {
    {"off", render::AntiAliasing::Off},
    {"fxaa", render::AntiAliasing::Fxaa},
    {"taa", render::AntiAliasing::Taa},
    {"gbaa", render::AntiAliasing::Gbaa}};

constexpr std::pair<const char*, render::ExposureMode> kExposures[] = {
    {"manual", render::ExposureMode::Manual}, {"auto", render::ExposureMode::Auto}};

constexpr std::pair<const char*, render::BrdfModel> kBrdfs[] = {
    {"ue4", render::BrdfModel::Ue4}, {"energy-conserving", render::BrdfModel::EnergyConserving}};

constexpr std::pair<const char*, render::AreaLightMode> kAreaLightModes[] = {
    {"representative", render::AreaLightMode::Representative}, {"ltc", render::AreaLightMode::Ltc}};

constexpr std::pair<const char*, render::HairSelfShadow> kHairSelfShadowModes[] = {
    {"off", render::HairSelfShadow::Off},
    {"map", render::HairSelfShadow::DepthMap},
    {"reference", render::HairSelfShadow::Reference}};

constexpr std::pair<const char*, render::AoMode> kAoModes[] = {
    {"off", render::AoMode::Off},
    {"gtao", render::AoMode::Gtao},
    {"reference", render::AoMode::Reference}};

constexpr std::pair<const char*, render::SsrMode> kSsrModes[] = {
    {"off", render::SsrMode::Off},
    {"hiz", render::SsrMode::Hiz},
    {"reference", render::SsrMode::Reference}};
constexpr std::pair<const char*, render::SkyOcclusionMode> kSkyOcclusionModes[] = {
    {"off", render::SkyOcclusionMode::Off},
    {"on", render::SkyOcclusionMode::On},
    {"reference", render::SkyOcclusionMode::Reference}};
constexpr std::pair<const char*, render::ScatteringMode> kScatteringModes[] = {
    {"off", render::ScatteringMode::Off},
    {"epipolar", render::ScatteringMode::Epipolar},
    {"brute-force", render::ScatteringMode::BruteForce}};
constexpr std::pair<const char*, render::VolumetricsMode> kVolumetricsModes[] = {
    {"off", render::VolumetricsMode::Off},
    {"volumes", render::VolumetricsMode::Volumes},
    {"froxels", render::VolumetricsMode::Froxels},
    {"reference", render::VolumetricsMode::Reference}};

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

}  // namespace

std::string ApplicationOptions::standardFlagsUsage() {
    return "  --headless                render without a window (also when there is no display)\n"
           "  --size WxH                image size (default 1280x720)\n"
           "  --frames N                stop after N frames (headless default: 1)\n"
           "  --input SCRIPT            replay recorded input (see input_script.h)\n"
           "  --capture FILE.png|.exr   write the last frame (may repeat)\n"
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
           "  --brdf ue4|energy-conserving   (default: the scene file's, else energy-conserving)\n"
           "  --area-lights representative|ltc   sphere and tube lights' integration "
           "(default: ltc)\n"
           "  --aa off|fxaa|taa|gbaa    antialiasing (default: the scene file's, else taa)\n"
           "  --msaa 1|2|4|8            samples per pixel of the forward (blended) pass, with\n"
           "                            --aa (default: the scene file's, else 1 = off)\n"
           "  --bloom FRACTION          radiance scattered into glare, 0 (off) to 1\n"
           "                            (default: the scene file's, else 0.04)\n"
           "  --render-scale FRACTION   width and height the scene renders at, 0.25 to 1,\n"
           "                            upscaled to the output (default: the preset's)\n"
           "  --culling on|off          frustum culling of draws (off: the reference)\n"
           "  --lod-error PIXELS        levels of detail: a coarser mesh strays at most this\n"
           "                            far, 0 to 8 (0: full meshes; default: the preset's)\n"
           "  --area-texture-cells N    textured rect lights by LTC: cells per side of the\n"
           "                            image, 1, 2, 4, 8 or 16 (default: the preset's)\n"
           "  --froxel-light-cap N      most plain lights per froxel cluster lighting the\n"
           "                            medium, 0 (all) to 4096 (default: the preset's)\n"
           "  --exposure manual|auto    the camera's EV100, or metered and adapted\n"
           "                            (default: the scene file's, else manual)\n"
           "  --exposure-compensation EV   auto exposure's bias (+ brightens)\n"
           "  --ao off|gtao|reference   sky light occlusion (default: the scene file's, else "
           "gtao)\n"
           "  --hair-self-shadow off|map|reference   hair's shadow on itself: none, the hair\n"
           "                            depth map's estimate (default) or every fibre counted\n"
           "  --quality low|medium|high|ultra   every technique's settings in one preset\n"
           "                            (default: the scene file's, else medium on a CPU\n"
           "                            device, high on a GPU; a flag below wins over it)\n"
           "  --ssr off|hiz|reference   screen-space reflections on glossy surfaces\n"
           "                            (default: the scene file's, else hiz)\n"
           "  --sky-occlusion off|on|reference  the scene's geometry blocking the sky's light\n"
           "  --volumetrics off|volumes|froxels|reference   light scattered in the medium\n"
           "                            (default: volumes when the scene has fog, else off)\n"
           "  --volume-proxies off|on   volumes: each light's proxy mesh rasterised, or tile\n"
           "                            lists (default: the scene file's, else off)\n"
           "  --fog SIGMA_S[,SIGMA_A[,G]]   a uniform medium (1/m, Henyey-Greenstein g),\n"
           "                            replacing the scene's fog\n"
           "  --atmosphere              a physically based sky (Earth's) instead of the EXR sky\n"
           "  --atmosphere off          no atmosphere, even where the scene has one\n"
           "  --sun-elevation DEG       the atmosphere's sun this high, keeping its azimuth\n"
           "  --time-of-day HH:MM       the atmosphere's sun where it stands then (solar time)\n"
           "  --scattering off|epipolar|brute-force   light shafts in the atmosphere's air\n"
           "                            (default: epipolar when the scene has an atmosphere)\n"
           "  --scattering-slices N     epipolar slices (default 512)\n"
           "  --scattering-samples N    samples per epipolar slice (default 256)\n"
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
        } else if (arg == "--brdf") {
            render::BrdfModel brdf{};
            if (!value() || !parseChoice(v, kBrdfs, brdf)) {
                return fail("--brdf needs ue4 or energy-conserving, got '" + v + "'");
            }
            options.brdf = brdf;
        } else if (arg == "--area-lights") {
            render::AreaLightMode mode{};
            if (!value() || !parseChoice(v, kAreaLightModes, mode)) {
                return fail("--area-lights needs representative or ltc, got '" + v + "'");
            }
            options.areaLights = mode;
        } else if (arg == "--hair-self-shadow") {
            render::HairSelfShadow mode{};
            if (!value() || !parseChoice(v, kHairSelfShadowModes, mode)) {
                return fail("--hair-self-shadow needs off, map or reference, got '" + v + "'");
            }
            options.hairSelfShadow = mode;
        } else if (arg == "--aa") {
            render::AntiAliasing aa{};
            if (!value() || !parseChoice(v, kAntiAliasing, aa)) {
                return fail("--aa needs off, fxaa, taa or gbaa, got '" + v + "'");
            }
            options.aa = aa;
        } else if (arg == "--msaa") {
            if (!value() || (v != "1" && v != "2" && v != "4" && v != "8")) {
                return fail("--msaa needs 1, 2, 4 or 8 samples per pixel, got '" + v + "'");
            }
            options.msaa = uint32_t(std::stoul(v));
        } else if (arg == "--render-scale") {
            float scale = 0.0f;
            if (!value() || !parseFloat(v, scale) || !(scale >= 0.25f && scale <= 1.0f)) {
                return fail(
                    "--render-scale needs a fraction of the output's size from 0.25 to "
                    "1, got '" +
                    v + "'");
            }
            options.renderScale = scale;
        } else if (arg == "--lod-error") {
            float pixels = 0.0f;
            if (!value() || !parseFloat(v, pixels) || !(pixels >= 0.0f && pixels <= 8.0f)) {
                return fail("--lod-error needs pixels from 0 (full meshes) to 8, got '" + v + "'");
            }
            options.lodPixelError = pixels;
        } else if (arg == "--area-texture-cells") {
            uint32_t cells = 0;
            if (!value() || !parseUint(v, cells) || cells == 0 || cells > 16 ||
                (cells & (cells - 1)) != 0) {
                return fail("--area-texture-cells needs 1, 2, 4, 8 or 16, got '" + v + "'");
            }
            options.areaTextureCells = cells;
        } else if (arg == "--froxel-light-cap") {
            uint32_t cap = 0;
            if (!value() || !parseUint(v, cap) || cap > 4096) {
                return fail("--froxel-light-cap needs a count from 0 (every light) to 4096, got '" +
                            v + "'");
            }
            options.froxelLightCap = cap;
        } else if (arg == "--culling") {
            if (!value() || (v != "on" && v != "off"))
                return fail("--culling needs on or off, got '" + v + "'");
            options.culling = v == "on";
        } else if (arg == "--bloom") {
            float bloom = 0.0f;
            if (!value() || !parseFraction(v, bloom)) {
                return fail("--bloom needs a fraction from 0 (off) to 1, got '" + v + "'");
            }
            options.bloom = bloom;
        } else if (arg == "--exposure") {
            render::ExposureMode exposure{};
            if (!value() || !parseChoice(v, kExposures, exposure)) {
                return fail("--exposure needs manual or auto, got '" + v + "'");
            }
            options.exposure = exposure;
        } else if (arg == "--exposure-compensation") {
            float compensation = 0.0f;
            if (!value()) return fail("--exposure-compensation needs a number of EV");
            const char* end = v.data() + v.size();
            auto [ptr, ec] = std::from_chars(v.data(), end, compensation);
            // Written so NaN fails too (from_chars reads "nan").
            if (ec != std::errc() || ptr != end || !(std::abs(compensation) <= 16.0f)) {
                return fail("--exposure-compensation needs EV from -16 to 16, got '" + v + "'");
            }
            options.exposureCompensation = compensation;
        } else if (arg == "--ao") {
            render::AoMode ao{};
            if (!value() || !parseChoice(v, kAoModes, ao)) {
                return fail("--ao needs off, gtao or reference, got '" + v + "'");
            }
            options.ao = ao;
        } else if (arg == "--quality") {
            const std::optional<content::QualityLevel> level =
                value() ? content::parseQualityLevel(v) : std::nullopt;
            if (!level) return fail("--quality needs low, medium, high or ultra, got '" + v + "'");
            options.quality = level;
        } else if (arg == "--ssr") {
            render::SsrMode ssr{};
            if (!value() || !parseChoice(v, kSsrModes, ssr)) {
                return fail("--ssr needs off, hiz or reference, got '" + v + "'");
            }
            options.ssr = ssr;
        } else if (arg == "--sky-occlusion") {
            render::SkyOcclusionMode mode{};
            if (!value() || !parseChoice(v, kSkyOcclusionModes, mode)) {
                return fail("--sky-occlusion needs off, on or reference, got '" + v + "'");
            }
            options.skyOcclusion = mode;
        } else if (arg == "--volumetrics") {
            render::VolumetricsMode mode{};
            if (!value() || !parseChoice(v, kVolumetricsModes, mode)) {
                return fail("--volumetrics needs off, volumes, froxels or reference, got '" + v +
                            "'");
            }
            options.volumetrics = mode;
        } else if (arg == "--volume-proxies") {
            if (!value() || (v != "off" && v != "on")) {
                return fail("--volume-proxies needs off or on, got '" + v + "'");
            }
            options.volumeProxies = v == "on";
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
        } else if (arg == "--scattering") {
            render::ScatteringMode mode{};
            if (!value() || !parseChoice(v, kScatteringModes, mode)) {
                return fail("--scattering needs off, epipolar or brute-force, got '" + v + "'");
            }
            options.scattering = mode;
        } else if (arg == "--scattering-slices" || arg == "--scattering-samples" ||
                   arg == "--scattering-initial-step") {
            std::uint32_t n = 0;
            const std::uint32_t least = arg == "--scattering-samples" ? 2u : 1u;
            if (!value() || !parseUint(v, n) || n < least || n > 4096) {
                return fail(arg + " needs a count from " + std::to_string(least) +
                            " to 4096, got '" + v + "'");
            }
            if (arg == "--scattering-slices") {
                options.scatteringSlices = n;
            } else if (arg == "--scattering-samples") {
                options.scatteringSamples = n;
            } else {
                options.scatteringSettings.initialStep = n;
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
    if (options.scatteringSlices || options.scatteringSamples) {
        const std::uint64_t slices = options.scatteringSlices.value_or(512);
        const std::uint64_t samples = options.scatteringSamples.value_or(256);
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
