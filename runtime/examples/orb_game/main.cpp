// candela-orb-game: steer a glowing orb through a dark level and collect every spark before
// time runs out, without touching the red sentinels. Written only against the engine's public
// headers (runtime, ecs, content), as a user's game would be.
//
//   candela-orb-game [run] [LEVEL.scene.json | REPLAY.input] [--headless] [--size WxH]
//                    [--frames N] [--input SCRIPT] [--capture FILE.png|.exr]... [--stats FILE]
//                    [--state FILE.json]
//
// Keys: WASD or arrows steer, R restarts. A REPLAY.input is recorded input for the default
// level (the same as --input); `run` is accepted so the golden-image harness can drive it.
#include <charconv>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "candela/content/atomic_file_write.h"
#include "candela/content/diagnostics.h"
#include "candela/ecs/transform.h"
#include "candela/runtime/application.h"
#include "candela/runtime/exit_code.h"
#include "orb_components.h"
#include "orb_level.h"
#include "orb_systems.h"

namespace {

using namespace candela::runtime;

constexpr const char* kUsage =
    "usage: candela-orb-game [run] [LEVEL.scene.json | REPLAY.input] [--headless] [--size WxH]\n"
    "                        [--frames N] [--input SCRIPT] [--capture FILE.png|.exr]...\n"
    "                        [--stats FILE.json] [--state FILE.json]\n";

bool parseUint(const std::string& text, uint32_t& value) {
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    return ec == std::errc() && ptr == text.data() + text.size();
}

// The final game state as JSON, for tests and for anyone scripting the game. Returns the
// error (path and OS error) or an empty string.
std::string writeState(const std::string& path, const orb::GameState& s, uint32_t frames,
                       candela::ecs::Vec3 orbAt) {
    nlohmann::json j = {{"status", orb::statusName(s.status)},
                        {"reason", s.reason},
                        {"score", s.score},
                        {"collected", s.collected},
                        {"total", s.total},
                        {"restarts", s.restarts},
                        {"elapsed_seconds", s.elapsedSeconds},
                        {"frames", frames},
                        {"orb_position", {orbAt.x, orbAt.y, orbAt.z}}};
    return candela::content::writeFileAtomically(path, j.dump(2) + '\n');
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    if (!args.empty() && args[0] == "run") args.erase(args.begin());
    ApplicationOptions options;
    options.title = "Orb";
    options.validation = validationModeFromEnvironment();
    std::string level = ORB_GAME_DIR "/level.scene.json";
    std::string inputPath, statePath;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto value = [&]() -> const std::string* {
            return i + 1 < args.size() ? &args[++i] : nullptr;
        };
        const std::string* v = nullptr;
        if (a == "--help" || a == "-h") {
            std::fputs(kUsage, stdout);
            return kExitOk;
        } else if (a == "--headless") {
            options.headless = true;
        } else if (a == "--size" && (v = value())) {
            size_t x = v->find('x');
            if (x == std::string::npos || !parseUint(v->substr(0, x), options.width) ||
                !parseUint(v->substr(x + 1), options.height) || options.width == 0 ||
                options.height == 0 || options.width > 16384 || options.height > 16384) {
                std::fprintf(stderr, "orb: --size needs WxH (1..16384), got '%s'\n", v->c_str());
                return kExitBadArguments;
            }
        } else if (a == "--frames" && (v = value())) {
            if (!parseUint(*v, options.frames) || options.frames == 0) {
                std::fprintf(stderr, "orb: --frames needs a positive integer, got '%s'\n",
                             v->c_str());
                return kExitBadArguments;
            }
        } else if (a == "--input" && (v = value())) {
            inputPath = *v;
        } else if (a == "--capture" && (v = value())) {
            options.captures.push_back({FrameCapture::kLastFrame, *v});
        } else if (a == "--stats" && (v = value())) {
            options.stats = *v;
        } else if (a == "--state" && (v = value())) {
            statePath = *v;
        } else if (!a.empty() && a[0] != '-' && a.ends_with(".input")) {
            inputPath = a;
        } else if (!a.empty() && a[0] != '-') {
            level = a;
        } else {
            std::fprintf(stderr, "orb: unknown or incomplete option '%s'\n%s", a.c_str(), kUsage);
            return kExitBadArguments;
        }
    }
    if (!inputPath.empty()) {
        std::string error;
        options.inputScript = InputScript::load(inputPath, error);
        if (!options.inputScript) {
            std::fprintf(stderr, "orb: %s\n", error.c_str());
            return kExitBadArguments;
        }
    }

    Application app(options);
    candela::content::Diagnostics diagnostics;
    const bool loaded = app.world().loadSceneFile(level, diagnostics);
    for (const auto& d : diagnostics.messages) {
        std::fprintf(stderr, "orb: %s\n", candela::content::formatDiagnostic(d).c_str());
    }
    if (!loaded) return kExitBadArguments;
    if (std::string error = orb::spawnLevel(app.world(), level); !error.empty()) {
        std::fprintf(stderr, "orb: %s\n", error.c_str());
        return kExitBadArguments;
    }
    app.setClearRadiance({0.002f, 0.002f, 0.004f, 1.0f});  // a dark night
    orb::addOrbSystems(app);

    const int exitCode = app.run();
    const orb::GameState* state = nullptr;
    app.world().registry.view<const orb::GameState>().each(
        [&](const orb::GameState& s) { state = &s; });
    candela::ecs::Vec3 orbAt{};
    app.world().registry.view<const orb::Orb, const candela::ecs::LocalTransform>().each(
        [&](const orb::Orb&, const candela::ecs::LocalTransform& local) {
            orbAt = local.position;
        });
    if (state) {
        std::printf("%s: score %d, sparks %d/%d, %.2f s, %u frames\n",
                    orb::statusName(state->status), state->score, state->collected, state->total,
                    state->elapsedSeconds, app.framesRendered());
        if (statePath.empty()) return exitCode;
        if (std::string error = writeState(statePath, *state, app.framesRendered(), orbAt);
            !error.empty()) {
            std::fprintf(stderr, "orb: %s\n", error.c_str());
            return exitCode == kExitOk ? kExitFailure : exitCode;
        }
    }
    return exitCode;
}
