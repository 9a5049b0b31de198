#include "run_scene.h"

#include <cstdio>

#include "candela/runtime/application.h"
#include "scene_source.h"

namespace candela::runtime {

int runScene(const RunOptions& options) {
    std::string error;
    std::optional<LoadedScene> scene = loadScene(options.scene, error);
    if (!scene) {
        std::fprintf(stderr, "candela: %s\n", error.c_str());
        return kExitBadArguments;
    }
    ApplicationOptions app;
    app.width = options.width;
    app.height = options.height;
    app.headless = options.headless;
    app.frames = options.frames;
    for (const std::filesystem::path& capture : options.captures) {
        app.captures.push_back({FrameCapture::kLastFrame, capture});
    }
    app.stats = options.stats;
    app.countLightPairs = options.stats.has_value();
    app.validation = options.validation;
    app.lightCulling = options.lightCulling;

    Application application(std::move(app));
    application.setWorld(std::move(scene->world));
    application.frameInputs() = scene->frame;
    if (scene->animate) {
        application.addSystem(
            "animate", [animate = scene->animate](SceneWorld& world, const FrameContext& frame) {
                animate(world, frame.seconds);
            });
    }
    return application.run();
}

}  // namespace candela::runtime
