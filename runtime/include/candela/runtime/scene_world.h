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
    // The BRDF the last scene file loaded asks for ("brdf"), if it names one.
    std::optional<content::SceneBrdf> sceneBrdf() const { return sceneBrdf_; }
    // The antialiasing the last scene file loaded asks for ("aa"), if it names one.
    std::optional<content::SceneAntiAliasing> sceneAntiAliasing() const {
        return sceneAntiAliasing_;
    }
    // The forward pass's MSAA samples the last scene file asks for ("msaa"), if it sets them.
    std::optional<uint32_t> sceneMsaa() const { return sceneMsaa_; }
    // The screen-space reflections the last scene file asks for ("ssr"), if it names them.
    std::optional<content::SceneSsrMode> sceneSsr() const { return sceneSsr_; }
    // The quality preset the last scene file asks for ("quality"), if it names one.
    std::optional<content::QualityLevel> sceneQuality() const { return sceneQuality_; }
    std::optional<content::SceneSkyOcclusionMode> sceneSkyOcclusion() const {
        return sceneSkyOcclusion_;
    }
    // Built-in scenes (the demo) ask for reflections as a scene file would.
    void setSceneSsr(std::optional<content::SceneSsrMode> mode) { sceneSsr_ = mode; }
    // The light shafts and volumetrics the last scene file asks for ("scattering",
    // "volumetrics"), if it names them.
    std::optional<content::SceneScatteringMode> sceneScattering() const { return sceneScattering_; }
    std::optional<content::SceneVolumetricsMode> sceneVolumetrics() const {
        return sceneVolumetrics_;
    }
    // Whether the last scene file asks for the per-light volumes' proxy meshes
    // ("volume_proxies"), if it says.
    std::optional<bool> sceneVolumeProxies() const { return sceneVolumeProxies_; }
    // The bloom strength the last scene file asks for ("bloom"; 0: off), if it sets one.
    std::optional<float> sceneBloom() const { return sceneBloom_; }
    // The exposure mode and compensation the last scene file asks for, if it sets them.
    std::optional<content::SceneExposure> sceneExposure() const { return sceneExposure_; }
    std::optional<float> sceneExposureCompensation() const { return sceneExposureCompensation_; }
    // The scene file's "ambient_occlusion" (mode, radius, intensity), if it has one; the
    // renderer reads radius and intensity every frame, so an editor's change shows at once.
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

private:
    struct FrameChecks;
    std::unique_ptr<FrameChecks> checks_;
    std::vector<std::unique_ptr<content::Model>> models_;
    content::AssetCache cache_;
    std::filesystem::path sceneFile_;
    std::optional<content::SceneBrdf> sceneBrdf_;
    std::vector<content::MaterialLayer> sceneMaterialLayers_;
    std::optional<content::SceneAntiAliasing> sceneAntiAliasing_;
    std::optional<uint32_t> sceneMsaa_;
    std::optional<content::SceneSsrMode> sceneSsr_;
    std::optional<content::QualityLevel> sceneQuality_;
    std::optional<content::SceneScatteringMode> sceneScattering_;
    std::optional<content::SceneVolumetricsMode> sceneVolumetrics_;
    std::optional<bool> sceneVolumeProxies_;
    std::optional<content::SceneSkyOcclusionMode> sceneSkyOcclusion_;
    std::optional<float> sceneBloom_;
    std::optional<content::SceneExposure> sceneExposure_;
    std::optional<float> sceneExposureCompensation_;
    std::optional<content::SceneAmbientOcclusion> sceneAmbientOcclusion_;
};

}  // namespace candela::runtime
