#pragma once
// What an Application run does: size, headless or windowed, frame count, captures, stats,
// recorded input and the renderer's choices. Kept apart from application.h so a game's
// option handling does not need the application loop.
#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "candela/content/components/fog.h"
#include "candela/content/quality.h"
#include "candela/content/render_settings.h"
#include "candela/render/renderer_options.h"
#include "candela/render/validation_mode.h"
#include "candela/runtime/input_script.h"

namespace candela::runtime {

// Writes the frame rendered at `frame` (kLastFrame: the run's last) to `path` (.png or .exr).
struct FrameCapture {
    static constexpr std::uint32_t kLastFrame = std::numeric_limits<std::uint32_t>::max();
    std::uint32_t frame = kLastFrame;
    std::filesystem::path path;
};

struct CommandLine;

// What a game does with command-line arguments that are not standard flags.
enum class OtherArguments {
    Refuse,  // an error naming the argument (a game with no flags of its own)
    Keep,    // returned in CommandLine::arguments, in order, for the game to read
};

struct ApplicationOptions {
    std::string title = "Candela";
    std::uint32_t width = 1280;
    std::uint32_t height = 720;
    bool headless = false;                 // also headless when no display is found
    std::uint32_t frames = 0;              // 0: until the window closes (headless: 1)
    double fixedStepSeconds = 1.0 / 30.0;  // scene time per frame when headless
    std::vector<FrameCapture> captures;
    std::optional<std::filesystem::path> stats;       // per-run JSON (see frame_stats.h)
    std::optional<std::filesystem::path> frameGraph;  // the last frame's graph as Graphviz
    bool countLightPairs = false;  // renderer counts light-pixel pairs (stats' culling figures)
    // --stats-work last: a run of known length counts the lighting pass's work on its last
    // frame only, so the other frames time the pass without the counting variant's cost.
    bool countWorkOnLastFrame = false;
    render::ValidationMode validation = render::ValidationMode::IfPresent;
    render::LightCulling lightCulling = render::LightCulling::Clustered;
    render::LightAssignmentDevice lightAssignment = render::LightAssignmentDevice::Auto;
    // The sky (image-based lighting and background): this file if set, else the world's Sky
    // component; a file that cannot be used gives a message and a neutral sky.
    std::optional<std::filesystem::path> environment;
    render::IblMode ibl = render::IblMode::SplitSum;
    // --quality low|medium|high|ultra; unset: the world's scene-file "quality", else the
    // device's level (content/quality.h: medium on a CPU device, high on a GPU). Every render
    // setting that neither `settings` nor the scene file chooses takes the preset's value.
    std::optional<content::QualityLevel> quality;
    // The render settings the command line chose (--aa, --ssr, --bloom...: one flag per row of
    // content/render_setting_table.h); they win over the scene file's.
    content::RenderSettingChoices settings;
    // --culling off: every view records every draw (RendererOptions::culling's reference).
    bool culling = true;
    // --physics-debug: every collider (green, triggers yellow) and contact point (red) drawn
    // as wires over the scene (runtime/src/physics_debug_view.h).
    bool physicsDebug = false;
    // --audio-capture FILE.wav: the mix a player would hear, 48 kHz 16-bit stereo, rendered
    // in step with the frames (headless only: a window plays to the sound device). The same
    // run gives the same bytes (audio/README.md).
    std::optional<std::filesystem::path> audioCapture;
    // --fog SIGMA_S[,SIGMA_A[,G]]: a uniform medium replacing the scene's Fog (or adding one).
    std::optional<content::Fog> fog;
    // --atmosphere: the default Earth atmosphere for a scene without an Atmosphere component
    // (a glTF too); its sky replaces the EXR sky. --sun-elevation DEG moves the sun to that
    // elevation keeping its azimuth; --time-of-day HH:MM places it by the atmosphere's latitude
    // and day of the year (render/README.md "Atmosphere"). Either gives the scene an atmosphere.
    bool atmosphere = false;
    // --scattering-initial-step, --scattering-threshold: epipolar sampling's parameters;
    // --scattering-density: the air's density scale (render/README.md "Light shafts").
    render::ScatteringSettings scatteringSettings;
    // --scattering-slices x --scattering-samples (the samples a frame may march) is at most
    // this.
    static constexpr uint64_t kMaxScatteringSamples = uint64_t(1) << 20;
    // --atmosphere off: none, even where the scene has an Atmosphere component.
    bool atmosphereOff = false;
    std::optional<float> sunElevationDegrees;
    std::optional<float> timeOfDayHours;
    // Replayed instead of window input; with it, windowed runs use the fixed step too.
    std::optional<InputScript> inputScript;
    // --record-input FILE.input: the run's input written as a script --input replays
    // (input_recorder.h); such a run takes the fixed step, so the replay sees the same frames.
    std::optional<std::filesystem::path> recordInput;
    bool captureCursor = false;  // window: hide the cursor and report raw motion (mouse look)

    // The standard flags every game gets (see standardFlagsUsage()): --headless, --frames N,
    // --size WxH, --input SCRIPT, --capture FILE.png|.exr (repeats), --stats FILE.json,
    // --step SECONDS, --validation, --lights, --light-assign, --frame-graph, --env, --ibl,
    // --quality, a flag per render setting (content/render_setting_table.h: --aa, --ssr...),
    // --culling, --physics-debug, --fog, --atmosphere, --sun-elevation, --time-of-day and the light
    // shafts' parameters.
    // --help prints the usage to stdout; a bad flag prints "<program>: <problem>" and the
    // usage to stderr. Either way the result holds no options and the exit code to return:
    //
    //   auto command = candela::runtime::ApplicationOptions::fromCommandLine(argc, argv);
    //   if (!command) return command.exitCode;
    //
    // `gameUsage` describes the game's own arguments (kept with OtherArguments::Keep) in the
    // usage text. Validation defaults to CANDELA_VALIDATION, as every test sets it.
    static CommandLine fromCommandLine(int argc, const char* const* argv,
                                       OtherArguments others = OtherArguments::Refuse,
                                       std::string_view gameUsage = {});
    // The standard flags, one per line, for a usage message.
    static std::string standardFlagsUsage();
};

struct CommandLine {
    std::optional<ApplicationOptions> options;  // empty after --help or a bad argument
    std::vector<std::string> arguments;         // the rest, with OtherArguments::Keep
    std::string error;                          // the problem, when there was one
    // Values taken as changed ("clamped: --fog scattering ..."): printed by fromCommandLine.
    std::vector<std::string> warnings;
    bool helpRequested = false;
    int exitCode = 0;  // ExitCode to return when options is empty: ok after --help, else 2
    explicit operator bool() const { return options.has_value(); }
};

// fromCommandLine without printing: `args` exclude the program name; `defaults` are the
// options before any flag (e.g. a game's own size).
CommandLine parseCommandLine(const std::vector<std::string>& args,
                             OtherArguments others = OtherArguments::Refuse,
                             ApplicationOptions defaults = {});

// CANDELA_VALIDATION=require|off|on (unset: on, i.e. IfPresent), as every test sets it.
render::ValidationMode validationModeFromEnvironment();

}  // namespace candela::runtime
