#include "app/editor_options.h"

#include <cstdlib>
#include <string_view>

namespace candela::editor {

namespace {

bool parseUnsigned(std::string_view text, uint32_t& out) {
    if (text.empty() || text.size() > 9) return false;
    uint32_t value = 0;
    for (char c : text) {
        if (c < '0' || c > '9') return false;
        value = value * 10 + uint32_t(c - '0');
    }
    out = value;
    return true;
}

}  // namespace

std::string editorUsage() {
    return "usage: candela-editor [<scene.json|.gltf|.glb>] [--script FILE] [--size WxH]\n"
           "                      [--frames N] [--validation off|on|require] [--physics-debug]\n";
}

std::optional<EditorOptions> parseEditorOptions(int argc, const char* const* argv,
                                                std::string& error, bool& helpRequested) {
    EditorOptions options;
    helpRequested = false;
    if (const char* env = std::getenv("CANDELA_VALIDATION")) {
        const std::string_view mode(env);
        if (mode == "require") options.validation = render::ValidationMode::Required;
        if (mode == "off") options.validation = render::ValidationMode::Off;
    }
    for (int i = 1; i < argc; ++i) {
        const std::string_view arg(argv[i]);
        auto value = [&](std::string_view name) -> const char* {
            if (i + 1 >= argc) {
                error = std::string(name) + " needs a value";
                return nullptr;
            }
            return argv[++i];
        };
        if (arg == "--help" || arg == "-h") {
            helpRequested = true;
            error = editorUsage();
            return std::nullopt;
        } else if (arg == "--script") {
            const char* v = value(arg);
            if (!v) return std::nullopt;
            options.script = v;
        } else if (arg == "--frames") {
            const char* v = value(arg);
            if (!v) return std::nullopt;
            if (!parseUnsigned(v, options.frames)) {
                error = "--frames: '" + std::string(v) + "' is not a frame count";
                return std::nullopt;
            }
        } else if (arg == "--size") {
            const char* v = value(arg);
            if (!v) return std::nullopt;
            const std::string_view size(v);
            const size_t x = size.find('x');
            uint32_t w = 0, h = 0;
            if (x == std::string_view::npos || !parseUnsigned(size.substr(0, x), w) ||
                !parseUnsigned(size.substr(x + 1), h) || w < 64 || h < 64 || w > 8192 || h > 8192) {
                error = "--size: '" + std::string(size) + "' is not WxH between 64 and 8192";
                return std::nullopt;
            }
            options.width = w;
            options.height = h;
        } else if (arg == "--physics-debug") {
            options.physicsDebug = true;
        } else if (arg == "--validation") {
            const char* v = value(arg);
            if (!v) return std::nullopt;
            const std::string_view mode(v);
            if (mode == "off") {
                options.validation = render::ValidationMode::Off;
            } else if (mode == "on") {
                options.validation = render::ValidationMode::IfPresent;
            } else if (mode == "require") {
                options.validation = render::ValidationMode::Required;
            } else {
                error = "--validation: '" + std::string(mode) + "' is not off, on or require";
                return std::nullopt;
            }
        } else if (!arg.empty() && arg[0] == '-') {
            error = "unknown option '" + std::string(arg) + "'";
            return std::nullopt;
        } else if (options.scene) {
            error = "more than one scene given ('" + options.scene->string() + "', '" +
                    std::string(arg) + "')";
            return std::nullopt;
        } else {
            options.scene = std::filesystem::path(arg);
        }
    }
    return options;
}

}  // namespace candela::editor
