#include "candela/content/scene_instantiation.h"

#include <candela/ecs/hierarchy.h>
#include <candela/ecs/transform.h>
#include <candela/ecs/view.h>

#include "candela/content/builtin_meshes.h"
#include "candela/content/component_validation.h"
#include "candela/content/components/animation.h"
#include "candela/content/components/mesh_instance.h"
#include "candela/content/components/name.h"
#include "candela/content/light_texture.h"
#include "candela/content/model_instantiation.h"
#include "local_transform.h"
#include "scene_animation.h"

#include <algorithm>
#include <unordered_map>

namespace candela::content {
namespace {

Transform fromEcs(const ecs::LocalTransform& local) {
    Transform t;
    t.translation = {local.position.x, local.position.y, local.position.z};
    t.rotation = {local.rotation.x, local.rotation.y, local.rotation.z, local.rotation.w};
    t.scale = {local.scale.x, local.scale.y, local.scale.z};
    return t;
}

ecs::Entity createWithTransform(ecs::Registry& registry, const std::string& name,
                                const Transform& transform) {
    const ecs::Entity e = registry.create();
    registry.emplace<Name>(e, Name{name});
    registry.emplace<ecs::LocalTransform>(e, toLocalTransform(transform));
    registry.emplace<ecs::WorldTransform>(e);
    return e;
}

// The entity's glTF model under it, and its AnimationPlayer moved onto the entity (where the
// scene file's "animation" block and the editor's inspector find it) and set to `animation`.
void instantiateSceneModel(ecs::Registry& registry, ecs::Entity e, const SceneEntity& source,
                           const std::string& pointer, const std::filesystem::path& sceneFile,
                           AssetCache& cache, Diagnostics& diagnostics) {
    const std::string& stored = source.model->gltfPath;
    registry.emplace<ModelInstance>(e, ModelInstance{stored});
    // The cache keeps the model alive as long as the cache lives.
    std::shared_ptr<const Model> model =
        cache.model(resolveScenePath(sceneFile, stored), diagnostics);
    if (!model) return;  // the loader named the file and the problem; saving keeps the path
    const std::vector<ecs::Entity> created = instantiateModel(registry, *model, e, stored);
    AnimationPlayer* first =
        created.empty() ? nullptr : registry.tryGet<AnimationPlayer>(created.front());
    if (first == nullptr) {
        if (source.animation) {
            diagnostics.error(sceneFile.string(), pointer + "/animation",
                              stored + " has no animation clips");
        }
        return;
    }
    AnimationPlayer player = std::move(*first);
    registry.remove<AnimationPlayer>(created.front());
    if (source.animation) {
        if (auto problem = restoreAnimationPlayer(*source.animation, player)) {
            diagnostics.error(sceneFile.string(), pointer + "/animation" + problem->pointer,
                              problem->message + "; the player starts over");
        }
    }
    registry.emplace<AnimationPlayer>(e, std::move(player));
}

}  // namespace

std::vector<ecs::Entity> instantiateScene(ecs::Registry& registry, const SceneDocument& scene,
                                          const std::filesystem::path& sceneFile, AssetCache& cache,
                                          Diagnostics& diagnostics) {
    std::vector<ecs::Entity> entities;
    entities.reserve(scene.entities.size());
    for (std::size_t i = 0; i < scene.entities.size(); ++i) {
        const SceneEntity& source = scene.entities[i];
        const ecs::Entity e = createWithTransform(registry, source.name, source.transform);
        registry.emplace<SceneMember>(e, SceneMember{static_cast<std::uint32_t>(i)});
        if (source.mesh && !source.mesh->builtin.empty()) {
            // The reader accepted only known names.
            const auto builtin = builtinMeshFromName(source.mesh->builtin);
            registry.emplace<MeshInstance>(e,
                                           MeshInstance{builtin ? &builtinMeshModel() : nullptr,
                                                        builtin ? std::int32_t(*builtin) : -1, ""});
        } else if (source.mesh) {
            std::shared_ptr<const Model> model =
                cache.model(resolveScenePath(sceneFile, source.mesh->gltfPath), diagnostics);
            const std::int32_t mesh = source.mesh->meshIndex;
            const bool hasMesh =
                model && mesh >= 0 && static_cast<std::size_t>(mesh) < model->meshes.size();
            if (model && !hasMesh) {
                diagnostics.error(sceneFile.string(), "/entities/" + std::to_string(i) + "/mesh",
                                  source.mesh->gltfPath + " has no mesh " + std::to_string(mesh));
            }
            // The cache keeps the model alive as long as the cache lives.
            registry.emplace<MeshInstance>(
                e, MeshInstance{hasMesh ? model.get() : nullptr, mesh, source.mesh->gltfPath});
            for (std::size_t o = 0; hasMesh && o < source.materialOverrides.size(); ++o) {
                const std::string at = "/entities/" + std::to_string(i) + "/materialOverrides/" +
                                       std::to_string(o) + "/material/";
                for (const ValueProblem& problem : validateMaterialTextures(
                         source.materialOverrides[o].material, model->textures.size())) {
                    diagnostics.warning(sceneFile.string(), at + problem.field, problem.message);
                }
            }
        }
        if (source.model) {
            instantiateSceneModel(registry, e, source, "/entities/" + std::to_string(i), sceneFile,
                                  cache, diagnostics);
        }
        if (!source.materialOverrides.empty()) {
            registry.emplace<MaterialOverrides>(e, MaterialOverrides{source.materialOverrides});
        }
        if (source.light) {
            Light light = *source.light;
            const auto texture = findLightTexture(light.texture);
            if (texture && !texture->image && !texture->file.empty()) {
                // A rect's emissive image (issue 15); unreadable: untextured, with an error.
                const std::filesystem::path file = resolveScenePath(sceneFile, texture->file);
                std::string problem;
                auto image = loadLightTexture(file, problem);
                if (image) {
                    light.texture = registerLightTexture(texture->file, std::move(image));
                } else {
                    diagnostics.error(sceneFile.string(),
                                      "/entities/" + std::to_string(i) + "/light/texture",
                                      "light '" + source.name + "': cannot use " + file.string() +
                                          ": " + problem + "; the rect is untextured");
                }
            }
            registry.emplace<Light>(e, light);
        }
        if (source.camera) registry.emplace<Camera>(e, *source.camera);
        if (source.sky) registry.emplace<Sky>(e, *source.sky);
        if (source.fog) registry.emplace<Fog>(e, *source.fog);
        if (source.hair) registry.emplace<HairGrowth>(e, *source.hair);
        if (source.rigidBody) registry.emplace<RigidBody>(e, *source.rigidBody);
        if (source.collider) registry.emplace<Collider>(e, *source.collider);
        if (source.atmosphere) registry.emplace<Atmosphere>(e, *source.atmosphere);
        if (source.audioSource) {
            // Resolved and absolute: the audio system has no scene file to be relative to, and
            // saveSceneFile writes it back relative to wherever the scene is saved.
            AudioSource audio = *source.audioSource;
            audio.clip = std::filesystem::absolute(resolveScenePath(sceneFile, audio.clip))
                             .lexically_normal()
                             .string();
            registry.emplace<AudioSource>(e, audio);
        }
        if (source.audioListener) registry.emplace<AudioListener>(e, *source.audioListener);
        if (!source.gameDataJson.empty())
            registry.emplace<GameData>(e, GameData{source.gameDataJson});
        entities.push_back(e);
    }
    // Parents may come later in the file, so links are made once every entity exists.
    for (std::size_t i = 0; i < scene.entities.size(); ++i) {
        const std::int32_t p = scene.entities[i].parent;
        if (p >= 0 && static_cast<std::size_t>(p) < entities.size()) {
            (void)ecs::setParent(registry, entities[i], entities[static_cast<std::size_t>(p)]);
        }
    }
    return entities;
}

SceneDocument captureScene(ecs::Registry& registry) {
    std::vector<std::pair<std::uint32_t, ecs::Entity>> members;
    registry.view<SceneMember>().each([&](ecs::Entity e, const SceneMember& member) {
        members.push_back({member.order, e});
    });
    std::sort(members.begin(), members.end(), [](const auto& a, const auto& b) {
        return a.first != b.first ? a.first < b.first : a.second.bits() < b.second.bits();
    });
    std::unordered_map<std::uint64_t, std::int32_t> indexOf;
    for (std::size_t i = 0; i < members.size(); ++i) {
        indexOf[members[i].second.bits()] = static_cast<std::int32_t>(i);
    }
    SceneDocument scene;
    scene.entities.reserve(members.size());
    for (const auto& [order, e] : members) {
        SceneEntity& out = scene.entities.emplace_back();
        if (const auto* name = registry.tryGet<Name>(e)) out.name = name->value;
        if (const auto* local = registry.tryGet<ecs::LocalTransform>(e))
            out.transform = fromEcs(*local);
        if (const ecs::Entity p = ecs::parentOf(registry, e); p != ecs::kNullEntity) {
            if (auto it = indexOf.find(p.bits()); it != indexOf.end()) out.parent = it->second;
        }
        if (const auto* mesh = registry.tryGet<MeshInstance>(e);
            mesh && mesh->model == &builtinMeshModel()) {
            MeshReference builtin;
            builtin.builtin = builtinMeshName(BuiltinMesh(mesh->mesh));
            out.mesh = builtin;
        } else if (mesh && !mesh->gltfPath.empty()) {
            out.mesh = MeshReference{mesh->gltfPath, mesh->mesh, ""};
        }
        if (const auto* model = registry.tryGet<ModelInstance>(e)) {
            out.model = ModelReference{model->gltfPath};
            if (const auto* player = registry.tryGet<AnimationPlayer>(e))
                out.animation = captureAnimationPlayer(*player);
        }
        if (const auto* overrides = registry.tryGet<MaterialOverrides>(e)) {
            out.materialOverrides = overrides->overrides;
        }
        if (const auto* light = registry.tryGet<Light>(e)) out.light = *light;
        if (const auto* camera = registry.tryGet<Camera>(e)) out.camera = *camera;
        if (const auto* sky = registry.tryGet<Sky>(e)) out.sky = *sky;
        if (const auto* fog = registry.tryGet<Fog>(e)) out.fog = *fog;
        if (const auto* hair = registry.tryGet<HairGrowth>(e)) out.hair = *hair;
        if (const auto* body = registry.tryGet<RigidBody>(e)) {
            out.rigidBody = *body;
            out.rigidBody->sleeping = false;  // the simulation's state, not the scene's
        }
        if (const auto* collider = registry.tryGet<Collider>(e)) out.collider = *collider;
        if (const auto* atmosphere = registry.tryGet<Atmosphere>(e)) out.atmosphere = *atmosphere;
        if (const auto* audio = registry.tryGet<AudioSource>(e)) out.audioSource = *audio;
        if (const auto* listener = registry.tryGet<AudioListener>(e)) out.audioListener = *listener;
        if (const auto* data = registry.tryGet<GameData>(e)) out.gameDataJson = data->json;
    }
    return scene;
}

}  // namespace candela::content
