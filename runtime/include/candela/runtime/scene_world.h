#pragma once
// The running scene: the ECS registry, the models its entities draw (kept alive here), and
// what makes a bare model viewable (a camera framing it, lights when it has none).
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "candela/content/asset_cache.h"
#include "candela/content/diagnostics.h"
#include "candela/content/model.h"
#include "candela/content/scene_file.h"
#include "candela/ecs/registry.h"
#include "candela/ecs/transform.h"
#include "candela/physics/physics_world.h"

namespace candela::runtime {

struct SceneBounds {
    float min[3] = {0, 0, 0};
    float max[3] = {0, 0, 0};
    bool empty = true;
};

class SceneWorld {
public:
    SceneWorld();
    ~SceneWorld();
    SceneWorld(const SceneWorld&) = delete;
    SceneWorld& operator=(const SceneWorld&) = delete;

    ecs::Registry registry;

    // A new entity that is drawn, lit or looked through as soon as a MeshInstance, Light or
    // Camera is added: it has a Name, a LocalTransform `at` and a WorldTransform.
    ecs::Entity spawn(const std::string& name = {}, const ecs::LocalTransform& at = {});

    // Loads a .gltf/.glb into the registry. False when nothing usable could be read; the
    // diagnostics name the file and element of every problem either way.
    // `parent` (optional) becomes the parent of the model's root nodes.
    bool loadGltf(const std::filesystem::path& path, content::Diagnostics& diagnostics,
                  ecs::Entity parent = ecs::kNullEntity);

    // Loads an engine scene file (JSON) into the registry; its glTF references load through
    // the world's asset cache. False when the file itself could not be read.
    bool loadSceneFile(const std::filesystem::path& path, content::Diagnostics& diagnostics);
    // Where an asset path stored in a component (a Sky's file) points: relative to the last
    // scene file loaded, else as it is.
    std::filesystem::path resolveAssetPath(const std::string& stored) const;
    // The render settings the last scene file chooses ("aa", "ssr", "bloom"...; unset where
    // it says nothing). Built-in scenes (the demo) choose theirs here, as a scene file would.
    const content::RenderSettingChoices& sceneSettings() const { return sceneSettings_; }
    content::RenderSettingChoices& sceneSettings() { return sceneSettings_; }
    // The quality preset the last scene file asks for ("quality"), if it names one.
    std::optional<content::QualityLevel> sceneQuality() const { return sceneQuality_; }
    // The scene file's "ambient_occlusion" radius and intensity, if it has them; the renderer
    // reads them every frame, so an editor's change shows at once.
    const std::optional<content::SceneAmbientOcclusion>& sceneAmbientOcclusion() const {
        return sceneAmbientOcclusion_;
    }
    void setSceneAmbientOcclusion(std::optional<content::SceneAmbientOcclusion> settings) {
        sceneAmbientOcclusion_ = settings;
    }
    // The last scene file's layer library ("materialLayers"; materials hold their own copies):
    // what the editor offers to add to a material and writes back.
    const std::vector<content::MaterialLayer>& sceneMaterialLayers() const {
        return sceneMaterialLayers_;
    }

    // Where the world's models, textures, skies and audio clips are loaded once.
    content::AssetCache& assetCache() { return cache_; }

    // Keeps a model alive for the lifetime of the world and returns it.
    const content::Model& adoptModel(std::unique_ptr<content::Model> model);

    // World-space bounds of everything drawn (after transform propagation).
    SceneBounds bounds();

    // A scene with no camera gets one looking at its bounds from the front-right, and a scene
    // with neither lights nor a sky (a Sky component, or `externalSky` such as `--env`) gets a
    // sun and a fill, so any glTF shows up recognisably; someone who passes a sky sees the sky
    // alone. Returns one line per thing added, for the caller to print.
    std::vector<std::string> addViewingDefaults(bool externalSky = false);

    // Once per frame before extraction (Application does it after the systems):
    //  - an entity with a MeshInstance, Light or Camera but no WorldTransform gets one (and an
    //    identity LocalTransform if it has none), so code that forgot them still draws it;
    //  - a Light or LocalTransform written without markChanged<T>() is found (its value moved
    //    but its change tick did not), marked, and named once on stderr (one comparison per
    //    light and transform: about 0.1 ms for 10,000 entities; checkUnmarkedChanges = false
    //    skips it);
    //  - transforms propagate.
    void updateTransforms();
    bool checkUnmarkedChanges = true;

    // The world's rigid bodies (physics/README.md), made on first use with physicsSettings.
    // Games ask it queries (physics_queries.h) and read its events.
    physics::PhysicsWorld& physics();
    bool hasPhysics() const { return physics_ != nullptr; }
    physics::PhysicsSettings physicsSettings;
    // False (the editor): bodies follow their components, for queries and --physics-debug,
    // but nothing moves on its own.
    bool simulatePhysics = true;
    // Application runs this every frame before transform propagation: once any entity has a
    // Collider, the physics world steps for `deltaSeconds` and its problems go to stderr.
    void stepPhysics(double deltaSeconds);

private:
    struct FrameChecks;
    std::unique_ptr<FrameChecks> checks_;
    std::vector<std::unique_ptr<content::Model>> models_;
    content::AssetCache cache_;
    std::filesystem::path sceneFile_;
    content::RenderSettingChoices sceneSettings_;
    std::optional<content::QualityLevel> sceneQuality_;
    std::vector<content::MaterialLayer> sceneMaterialLayers_;
    std::optional<content::SceneAmbientOcclusion> sceneAmbientOcclusion_;
    std::unique_ptr<physics::PhysicsWorld> physics_;  // before the registry goes
};

}  // namespace candela::runtime
