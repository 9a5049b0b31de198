// candela-orb-game: steer a glowing orb through a dark level and collect every spark before
// time runs out, without touching the red sentinels. Written only against the engine's public
// headers (runtime, ecs, content), as a user's game would be.
//
//   candela-orb-game [run] [LEVEL.scene.json | REPLAY.input] [--state FILE.json]
//                    [--mascot MODEL.glb]
//                    [the standard flags: --headless --size WxH --frames N --input SCRIPT
//                     --capture FILE.png|.exr --stats FILE.json ... (--help lists them)]
//
// Keys: WASD or arrows steer, R restarts. A REPLAY.input is recorded input for the default
// level (the same as --input); `run` is accepted so the golden-image harness can drive it.
// --mascot adds an animated glTF character (e.g. the shared Fox) that cheers when the player
// scores and sulks when the game is lost; --state then logs its animation every frame.
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "candela/content/atomic_file_write.h"
#include "candela/content/components/animation.h"
#include "candela/content/diagnostics.h"
#include "candela/content/model.h"
#include "candela/ecs/transform.h"
#include "candela/runtime/application.h"
#include "candela/runtime/exit_code.h"
#include "orb_components.h"
#include "orb_level.h"
#include "orb_systems.h"
#include "orb_ui.h"

namespace {

using namespace candela::runtime;

constexpr const char* kGameUsage =
    "[run] [LEVEL.scene.json | REPLAY.input] [--state FILE.json] [--mascot MODEL.glb]\n"
    "                 [--bindings FILE.json]  (steer_x, steer_z, restart: see orb_systems.cpp)\n"
    "                 [--title]  (start on the title menu, as a window without --input does)";

// The mascot's clips and its animation state each frame: [frame, clip, time, next clip (-1:
// none), crossfade weight, score, status].
nlohmann::json mascotJson(const orb::Mascot& m, const candela::content::AnimationPlayer& player) {
    nlohmann::json clips = nlohmann::json::array();
    for (const auto& clip : player.model->animations)
        clips.push_back({{"name", clip.name}, {"duration", clip.duration}});
    nlohmann::json frames = nlohmann::json::array();
    for (const orb::Mascot::Row& r : m.log) {
        frames.push_back({r.frame, r.clip, r.time, r.nextClip, r.fadeWeight, r.score,
                          orb::statusName(r.status)});
    }
    return {{"clips", std::move(clips)},
            {"idle", m.idleClip},
            {"cheer", m.cheerClip},
            {"sulk", m.sulkClip},
            {"frames", std::move(frames)}};
}

// The final game state as JSON, for tests and for anyone scripting the game. Returns the
// error (path and OS error) or an empty string.
std::string writeState(const std::string& path, const orb::GameState& s, uint32_t frames,
                       candela::ecs::Vec3 orbAt, const nlohmann::json& mascot) {
    nlohmann::json j = {{"status", orb::statusName(s.status)},
                        {"reason", s.reason},
                        {"score", s.score},
                        {"collected", s.collected},
                        {"total", s.total},
                        {"restarts", s.restarts},
                        {"elapsed_seconds", s.elapsedSeconds},
                        {"frames", frames},
                        {"orb_position", {orbAt.x, orbAt.y, orbAt.z}}};
    if (!mascot.is_null()) j["mascot"] = mascot;
    return candela::content::writeFileAtomically(path, j.dump(2) + '\n');
}

}  // namespace

int main(int argc, char** argv) {
    // `run` first is accepted so the golden-image harness can drive the game like `candela`.
    std::vector<const char*> arguments(argv, argv + argc);
    if (arguments.size() > 1 && std::string(arguments[1]) == "run")
        arguments.erase(arguments.begin() + 1);
    CommandLine command = ApplicationOptions::fromCommandLine(
        int(arguments.size()), arguments.data(), OtherArguments::Keep, kGameUsage);
    if (!command) return command.exitCode;
    ApplicationOptions options = *command.options;
    options.title = "Orb";
    std::string level = ORB_GAME_DIR "/level.scene.json";
    std::string inputPath, statePath, mascotPath, bindingsPath;
    // The title menu: a player's window starts on it; replays and headless runs start playing
    // unless --title asks for it (a replay that clicks Play, a recording made on the title).
    std::optional<bool> title;
    const std::vector<std::string>& args = command.arguments;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a == "--state" && i + 1 < args.size()) {
            statePath = args[++i];
        } else if (a == "--mascot" && i + 1 < args.size()) {
            mascotPath = args[++i];
        } else if (a == "--bindings" && i + 1 < args.size()) {
            bindingsPath = args[++i];
        } else if (a == "--title") {
            title = true;
        } else if (!a.empty() && a[0] != '-' && a.ends_with(".input")) {
            inputPath = a;  // a replay: the same as --input
        } else if (!a.empty() && a[0] != '-') {
            level = a;
        } else {
            std::fprintf(stderr, "orb: unknown or incomplete option '%s'\n", a.c_str());
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
    if (!mascotPath.empty()) {
        candela::content::Diagnostics mascotDiagnostics;
        if (std::string error = orb::spawnMascot(app.world(), mascotPath, mascotDiagnostics);
            !error.empty()) {
            for (const auto& d : mascotDiagnostics.messages)
                std::fprintf(stderr, "orb: %s\n", candela::content::formatDiagnostic(d).c_str());
            std::fprintf(stderr, "orb: %s\n", error.c_str());
            return kExitBadArguments;
        }
    }
    app.setClearRadiance({0.002f, 0.002f, 0.004f, 1.0f});  // a dark night
    // A bindings file the player edited: its problems are named and the defaults stand.
    candela::runtime::InputActions& actions = orb::addOrbControls(app.world());
    if (!bindingsPath.empty()) {
        if (std::string error = actions.loadBindings(bindingsPath); !error.empty()) {
            std::fprintf(stderr, "orb: %s; the default controls stand\n", error.c_str());
        }
    }
    orb::addOrbUi(app, title.value_or(!options.headless && !options.inputScript));
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
        nlohmann::json mascot;
        app.world().registry.view<const orb::Mascot>().each([&](const orb::Mascot& m) {
            if (auto* p = app.world().registry.tryGet<candela::content::AnimationPlayer>(m.player))
                mascot = mascotJson(m, *p);
        });
        if (std::string error = writeState(statePath, *state, app.framesRendered(), orbAt, mascot);
            !error.empty()) {
            std::fprintf(stderr, "orb: %s\n", error.c_str());
            return exitCode == kExitOk ? kExitFailure : exitCode;
        }
    }
    return exitCode;
}
