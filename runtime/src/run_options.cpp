#include "run_options.h"

namespace candela::runtime {

std::string runUsage() {
    return "usage: candela run <scene.json|scene.gltf|scene.glb|builtin:triangle> [options]\n"
           "       candela demo [options]\n"
           "options:\n" +
           ApplicationOptions::standardFlagsUsage() +
           "  --capture-each DIR        write every frame as DIR/frame_NN.png (needs --frames)\n"
           "  --summary FILE.md         write a per-frame table\n"
           "  --animation NAME|INDEX    the glTF animation clip to play, looping (default: the\n"
           "                            first); headless runs advance it by --step per frame\n"
           "  --overlay|--no-overlay    the stats overlay (default: on in the demo's window)\n";
}

ParseResult parseRunOptions(const std::vector<std::string>& args) {
    ParseResult result;
    ApplicationOptions defaults;
    defaults.validation = validationModeFromEnvironment();
    CommandLine standard = parseCommandLine(args, OtherArguments::Keep, std::move(defaults));
    if (standard.helpRequested) {
        result.helpRequested = true;
        return result;
    }
    if (!standard.options) {
        result.error = standard.error;
        return result;
    }
    RunOptions options;
    options.app = std::move(*standard.options);
    auto fail = [&](std::string message) {
        result.error = std::move(message);
        return result;
    };
    const std::vector<std::string>& rest = standard.arguments;
    for (size_t i = 0; i < rest.size(); ++i) {
        const std::string& arg = rest[i];
        const std::string* value = i + 1 < rest.size() ? &rest[i + 1] : nullptr;
        if (arg == "--overlay") {
            options.overlay = true;
        } else if (arg == "--no-overlay") {
            options.overlay = false;
        } else if (arg == "--capture-each") {
            if (!value) return fail("--capture-each needs a directory");
            options.captureEach = *value;
            ++i;
        } else if (arg == "--animation") {
            if (!value) return fail("--animation needs a clip name or index");
            options.animation = *value;
            ++i;
        } else if (arg == "--summary") {
            if (!value) return fail("--summary needs a file name");
            options.summary = *value;
            ++i;
        } else if (!arg.empty() && arg[0] == '-') {
            return fail("unknown option '" + arg + "'");
        } else if (options.scene.empty()) {
            options.scene = arg;
        } else {
            return fail("more than one scene given: '" + options.scene + "' and '" + arg + "'");
        }
    }
    result.options = std::move(options);
    return result;
}

}  // namespace candela::runtime
