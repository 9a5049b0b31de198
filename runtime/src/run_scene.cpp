#include "run_scene.h"

#include <cstdio>

#include "candela/content/components/animation.h"
#include "candela/runtime/scene_source.h"
#include "run_summary.h"

namespace candela::runtime {

namespace {

std::filesystem::path eachFramePath(const std::filesystem::path& dir, uint32_t frame) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%02u.png", frame);
    return dir / name;
}

// --animation: every AnimationPlayer in the scene plays that clip from time 0.
std::string selectAnimation(LoadedScene& scene, const std::string& clip) {
    if (!scene.world) return "--animation: this scene has no animations";
    std::string problem = "--animation: the scene has no animations";
    scene.world->registry.view<content::AnimationPlayer>().each(
        [&](ecs::Entity, content::AnimationPlayer& player) {
            problem = player.playByNameOrIndex(clip);
        });
    return problem;
}

}  // namespace

int runScene(const RunOptions& options, std::vector<std::shared_ptr<FrameLayer>> layers) {
    std::string error;
    std::optional<LoadedScene> scene =
        loadScene(options.scene, error,
                  options.app.environment.has_value() || options.app.atmosphere ||
                      options.app.sunElevationDegrees || options.app.timeOfDayHours);
    if (!scene) {
        std::fprintf(stderr, "candela: %s\n", error.c_str());
        return kExitBadArguments;
    }
    if (options.animation) {
        if (std::string problem = selectAnimation(*scene, *options.animation); !problem.empty()) {
            std::fprintf(stderr, "candela: %s: %s\n", options.scene.c_str(), problem.c_str());
            return kExitBadArguments;
        }
    }
    ApplicationOptions app = options.app;
    if (options.captureEach) {
        if (app.frames == 0) {
            std::fprintf(stderr, "candela: --capture-each needs --frames N\n");
            return kExitBadArguments;
        }
        std::error_code ec;
        std::filesystem::create_directories(*options.captureEach, ec);
        if (ec) {
            std::fprintf(stderr, "candela: %s: cannot create directory: %s\n",
                         options.captureEach->c_str(), ec.message().c_str());
            return kExitBadArguments;
        }
        for (uint32_t i = 0; i < app.frames; ++i) {
            app.captures.push_back({i, eachFramePath(*options.captureEach, i)});
        }
    }
    // The overlay shows culling efficiency, which needs the pair counts too.
    app.countLightPairs = app.stats.has_value() || options.summary.has_value() || !layers.empty();

    const double step = app.fixedStepSeconds;
    Application application(std::move(app));
    application.setWorld(std::move(scene->world));
    application.frameInputs() = scene->frame;
    if (scene->addSystems) scene->addSystems(application);
    for (auto& layer : layers)
        application.addLayer(std::move(layer));
    int exitCode = application.run();
    if (options.summary && application.framesRendered() > 0) {
        if (std::string e =
                writeRunSummary(*options.summary, scene->name, step, application.stats());
            !e.empty()) {
            std::fprintf(stderr, "candela: %s\n", e.c_str());
            if (exitCode == kExitOk) exitCode = kExitFailure;
        }
    }
    return exitCode;
}

}  // namespace candela::runtime
