// minimal-game: steer the white ball with WASD and touch the four orbiting lights; each touch
// scores a point, chimes and knocks that light ahead along its orbit; a button resets the
// score. The whole game is this file, the level (level.scene.json: walls, lights that are
// trigger colliders, the chime's sound) and a CMakeLists.txt of find_package(Candela).
//   minimal-game                                  # a window (headless without a display)
//   minimal-game --headless --frames 150 --input replays/collect.input --capture shot.png
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "candela/content/components/audio_source.h"
#include "candela/content/components/light.h"
#include "candela/content/components/name.h"
#include "candela/content/game_data.h"
#include "candela/ecs/transform.h"
#include "candela/physics/character_controller.h"
#include "candela/runtime/application.h"
#include "candela/runtime/debug_text.h"
#include "candela/runtime/exit_code.h"
#include "candela/runtime/game_ui.h"

using namespace candela;
using runtime::Key;

struct Orbit {  // a light circling the centre of the arena
    float radius = 0, angle = 0, radiansPerSecond = 0;
};

int main(int argc, char** argv) {
    // --headless --frames --size --input --capture --stats ... (--help lists them)
    runtime::CommandLine command = runtime::ApplicationOptions::fromCommandLine(argc, argv);
    if (!command) return command.exitCode;
    command.options->title = "Minimal game";
    runtime::Application app(*command.options);

    content::Diagnostics diagnostics;
    const bool loaded = app.world().loadSceneFile(LEVEL_FILE, diagnostics);
    for (const content::Diagnostic& d : diagnostics.messages)
        std::fprintf(stderr, "%s\n", content::formatDiagnostic(d).c_str());
    if (!loaded) return runtime::kExitBadArguments;

    // Find the ball and the lights first: adding components inside view().each is refused.
    ecs::Registry& registry = app.world().registry;
    ecs::Entity ball = ecs::kNullEntity, chime = ecs::kNullEntity;
    std::vector<std::pair<ecs::Entity, Orbit>> orbiters;
    registry.view<const content::Name, const ecs::LocalTransform>().each(
        [&](ecs::Entity e, const content::Name& name, const ecs::LocalTransform& t) {
            if (name.value == "ball") ball = e;
            if (name.value == "chime") chime = e;  // a sound that follows the ball
            if (const auto* data = registry.tryGet<content::GameData>(e)) {  // the level's
                const float speed = content::GameDataReader(*data).value("orbitSpeed", 0.0f);
                orbiters.push_back({e,
                                    {std::hypot(t.position.x, t.position.z),
                                     std::atan2(t.position.z, t.position.x), speed}});
            }
        });
    for (auto& [e, orbit] : orbiters)
        registry.emplace<Orbit>(e, orbit);
    if (ball.isNull() || chime.isNull()) return runtime::kExitBadArguments;
    registry.emplace<physics::CharacterController>(
        ball, physics::CharacterController{.radius = 0.5f, .height = 1.0f});

    app.addSystem("orbit", [](runtime::SceneWorld& world, const runtime::FrameContext& frame) {
        world.registry.view<ecs::LocalTransform, Orbit>().each([&](ecs::Entity e,
                                                                   ecs::LocalTransform& t,
                                                                   Orbit& o) {
            o.angle += o.radiansPerSecond * float(frame.deltaSeconds);
            t.position = {o.radius * std::cos(o.angle), t.position.y, o.radius * std::sin(o.angle)};
            world.registry.markChanged<ecs::LocalTransform>(e);  // so it is drawn there
        });
    });

    auto ui = std::make_shared<runtime::GameUi>();  // a Reset button, bottom left
    app.addLayer(ui);
    const auto reset = ui->tree().add(gameui::button("Reset", {0, 1, 0, 1}, {16, -56, 136, -16}));
    int score = 0;
    app.addSystem("player", [&](runtime::SceneWorld& world, const runtime::FrameContext& frame) {
        for (const gameui::UiEvent& e : ui->events())
            score = e.widget == reset ? 0 : score;
        const runtime::InputState& keys = frame.keys();
        const ecs::Vec3 direction{float(keys.down(Key::D)) - float(keys.down(Key::A)), 0.0f,
                                  float(keys.down(Key::S)) - float(keys.down(Key::W))};
        world.registry.get<physics::CharacterController>(ball).desiredVelocity = direction * 5.0f;
        // A light's trigger collider touched by the ball (physics, last frame).
        for (const physics::TriggerEvent& touch : world.physics().events().triggers) {
            if (touch.other != ball || touch.phase != physics::ContactPhase::Begin) continue;
            if (Orbit* orbit = world.registry.tryGet<Orbit>(touch.trigger)) {
                ++score;
                orbit->angle += 2.0f;  // knocked ahead along its orbit
                world.registry.patch<content::AudioSource>(chime, [](auto& s) { s.play(); });
            }
        }
        runtime::debugText(world).print(16, 16, "SCORE " + std::to_string(score), {1, 0.9f, 0.3f});
    });

    const int exitCode = app.run();
    std::printf("score %d after %u frames\n", score, app.framesRendered());
    return exitCode;
}
