#pragma once
// The engine scene file: versioned JSON (nlohmann-json) listing entities and their components.
// Assets are referenced by paths relative to the scene file. Saving then loading gives back
// identical data, floats bit for bit. Saving is atomic (writeFileAtomically): a temporary file
// in the same directory is written, flushed to disk and renamed over the old file, so a crash
// or a full disk leaves either the old or the new scene, never a mix. The old file's mode and
// owner are kept, a symbolic link is written through to its target, and a read-only file is
// only replaced when the caller asks.
//
//   SceneDocument scene;
//   SceneEntity& helmet = scene.entities.emplace_back();
//   helmet.name = "helmet";
//   helmet.mesh = MeshReference{"models/DamagedHelmet.glb", 0};
//   if (std::string error = saveSceneFile("level.scene.json", scene); !error.empty()) ...
//   Diagnostics diagnostics;
//   std::optional<SceneDocument> loaded = loadSceneFile("level.scene.json", diagnostics);
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "candela/content/atomic_file_write.h"
#include "candela/content/components/atmosphere.h"
#include "candela/content/components/audio_listener.h"
#include "candela/content/components/audio_source.h"
#include "candela/content/components/camera.h"
#include "candela/content/components/collider.h"
#include "candela/content/components/fog.h"
#include "candela/content/components/hair_growth.h"
#include "candela/content/components/light.h"
#include "candela/content/components/rigid_body.h"
#include "candela/content/components/scene_components.h"
#include "candela/content/components/sky.h"
#include "candela/content/diagnostics.h"
#include "candela/content/material.h"
#include "candela/content/model.h"
#include "candela/content/quality.h"
#include "candela/content/render_settings.h"

namespace candela::content {

inline constexpr int kSceneFileVersion = 1;

struct MeshReference {
    std::string gltfPath;        // relative to the scene file
    std::int32_t meshIndex = 0;  // into the glTF's meshes
    std::string builtin;         // instead of a glTF: "plane", "box" or "sphere" (builtin_meshes.h)

    bool operator==(const MeshReference&) const = default;
};

// A whole glTF model under the entity ("model": {"gltf": ...}): its node hierarchy, skins and
// clips, made as the entity's children the way instantiateModel() makes them. Those children
// are not scene members: loading makes them again from the glTF.
struct ModelReference {
    std::string gltfPath;  // relative to the scene file

    bool operator==(const ModelReference&) const = default;
};

// A clip of the entity's model, by name (when `name` is not empty) or by index.
struct SceneClip {
    std::string name;
    std::int32_t index = 0;

    bool operator==(const SceneClip&) const = default;
};

// The model's AnimationPlayer state ("animation": {...}), restored on loading and written back
// on saving. Mirrors AnimationPlayer (components/animation.h) with clips named.
struct SceneAnimation {
    SceneClip clip;
    float time = 0;   // seconds into the clip
    float speed = 1;  // finite; negative plays backwards
    bool loop = true;
    bool playing = true;
    // A crossfade in progress ("crossfade": {"clip", "time", "duration", "elapsed"}).
    struct Crossfade {
        SceneClip clip;
        float time = 0;      // seconds into the target clip
        float duration = 1;  // > 0
        float elapsed = 0;   // 0..duration

        bool operator==(const Crossfade&) const = default;
    };
    std::optional<Crossfade> crossfade;

    bool operator==(const SceneAnimation&) const = default;
};

struct SceneEntity {
    std::string name;
    Transform transform;             // local, relative to the parent
    std::int32_t parent = kNoIndex;  // index into SceneDocument::entities
    std::optional<MeshReference> mesh;
    std::optional<ModelReference> model;
    // Only with `model`; unset: the model's first clip from time 0, looping.
    std::optional<SceneAnimation> animation;
    std::vector<MaterialOverride> materialOverrides;
    std::optional<Light> light;
    std::optional<Camera> camera;
    std::optional<Sky> sky;
    std::optional<Fog> fog;  // "fog": {"scattering", "absorption", "anisotropy", ...}
    // "atmosphere": {"rayleighScattering": [r, g, b], "mieScattering", ...} (atmosphere.h)
    std::optional<Atmosphere> atmosphere;
    // "hair": {"count", "length", "seed", "style": {the glTF extras.hair keys}}, only with a
    // "mesh": fur grown on it (components/hair_growth.h).
    std::optional<HairGrowth> hair;
    // "rigidBody": {"type": "dynamic"|"kinematic"|"static", "mass", "friction", "restitution",
    // ...} and "collider": {"shape": "sphere"|"box"|"capsule"|"cylinder"|"convexHull"|
    // "triangleMesh", "radius", "halfExtents", "height", "trigger", "layer", "mask"}
    // (physics/README.md); a collider without a rigid body is static.
    std::optional<RigidBody> rigidBody;
    std::optional<Collider> collider;
    // "audioSource": {"clip" (relative to the scene file), "gain", "pitch", "loop", "spatial",
    // "minDistance", "maxDistance", "rolloff", "playing"} and "audioListener": {"gain"}
    // (audio/README.md).
    std::optional<AudioSource> audioSource;
    std::optional<AudioListener> audioListener;
    // Free-form game data as JSON text; empty when none. Loading gives the canonical form
    // (compact, object keys sorted), which saving and loading again preserves exactly.
    std::string gameDataJson;
};

// The scene file's "ambient_occlusion": {"mode", "radius", "intensity"}. The mode is a render
// setting (SceneDocument::settings.ao, the command line's --ao overrides it); radius and
// intensity are the scene's own, sent to the renderer every frame.
struct SceneAmbientOcclusion {
    float radius = 1.5f;     // metres, > 0
    float intensity = 1.0f;  // 0..1

    bool operator==(const SceneAmbientOcclusion&) const = default;
};

struct SceneDocument {
    std::vector<SceneEntity> entities;
    // The render settings the scene chooses, each under its key (render_setting_table.h:
    // "aa", "ssr", "bloom", ...); the command line's flags override them, and an unset one
    // takes the quality preset's value.
    RenderSettingChoices settings;
    // Top-level "quality": "low", "medium", "high" or "ultra" (quality.h), every technique's
    // preset; the command line's --quality overrides it. Unset: the device's level.
    std::optional<QualityLevel> quality;
    std::optional<SceneAmbientOcclusion> ambientOcclusion;  // radius and intensity; unset: defaults
    // Top-level "materialLayers": the shared layer library, by unique name. A material's
    // "layers" (at most kMaxMaterialLayers) name library layers; each copy starts as the
    // library's and may change any of its parameters, and is written back in full.
    std::vector<MaterialLayer> materialLayers;
};

// Where an asset path stored in a scene file points: relative paths are relative to the
// scene file's directory; absolute paths stay as they are.
inline std::filesystem::path resolveScenePath(const std::filesystem::path& sceneFile,
                                              const std::string& stored) {
    const std::filesystem::path path(stored);
    return path.is_absolute() ? path : sceneFile.parent_path() / path;
}

// Returns nullopt when the file cannot be read or is not a scene file of a supported
// version. Otherwise returns the scene; components that were malformed are left out with an
// error naming the file and the JSON pointer (e.g. "/entities/3/light/lumens").
std::optional<SceneDocument> loadSceneFile(const std::filesystem::path& path,
                                           Diagnostics& diagnostics);
std::optional<SceneDocument> parseSceneJson(std::span<const std::byte> bytes,
                                            const std::string& name, Diagnostics& diagnostics);

// Serialises to JSON text (what saveSceneFile writes). Empty string and `error` set when the
// scene holds values JSON cannot represent (NaN/Inf) or malformed game data.
std::string sceneToJson(const SceneDocument& scene, std::string& error);

// Returns an empty string on success, else what went wrong (the old file is then untouched).
std::string saveSceneFile(const std::filesystem::path& path, const SceneDocument& scene,
                          AtomicWriteOptions options = {});

}  // namespace candela::content
