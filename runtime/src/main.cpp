// The candela executable: `candela run <scene> [options]` and `candela demo [options]`.
#include <cstdio>
#include <string>
#include <vector>

#include "run_options.h"
#include "run_scene.h"
#include "stats_overlay.h"

using namespace candela::runtime;

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty() || args[0] == "--help" || args[0] == "-h") {
        std::fputs(runUsage().c_str(), args.empty() ? stderr : stdout);
        return args.empty() ? kExitBadArguments : kExitOk;
    }
    const std::string command = args[0];
    args.erase(args.begin());
    if (command != "run" && command != "demo") {
        std::fprintf(stderr, "candela: unknown command '%s'\n%s", command.c_str(),
                     runUsage().c_str());
        return kExitBadArguments;
    }
    ParseResult parsed = parseRunOptions(args);
    if (parsed.helpRequested) {
        std::fputs(runUsage().c_str(), stdout);
        return kExitOk;
    }
    if (!parsed.options) {
        std::fprintf(stderr, "candela: %s\n%s", parsed.error.c_str(), runUsage().c_str());
        return kExitBadArguments;
    }
    RunOptions options = *parsed.options;
    if (command == "demo" && options.scene.empty()) options.scene = "builtin:demo";
    // The demo adapts its exposure to what the camera sees (issue 24); --exposure overrides.
    if (command == "demo" && !options.app.settings.exposure)
        options.app.settings.exposure = candela::content::FrameExposure::Auto;
    // The stats overlay: on in the demo's window; --overlay also draws it headless and on
    // `run` (the figures change run to run, so captures with it are not reproducible).
    std::vector<std::shared_ptr<FrameLayer>> layers;
    const bool overlay = options.overlay.value_or(command == "demo");
    if (overlay) layers.push_back(std::make_shared<StatsOverlay>(options.overlay.value_or(false)));
    return runScene(options, std::move(layers));
}
