#include "model/entity_snapshot.h"

#include "candela/ecs/hierarchy.h"
#include "model/editor_scene.h"

namespace candela::editor {

namespace {

template <class T>
std::optional<T> copyOf(ecs::Registry& registry, ecs::Entity e) {
    const T* value = registry.tryGet<T>(e);
    return value ? std::optional<T>(*value) : std::nullopt;
}

template <class T>
void emplaceIf(ecs::Registry& registry, ecs::Entity e, const std::optional<T>& value) {
    if (value) registry.emplace<T>(e, *value);
}

}  // namespace

EntitySnapshot snapshotEntity(EditorScene& scene, ecs::Entity e) {
    ecs::Registry& registry = scene.registry();
    EntitySnapshot s;
    s.id = scene.idOf(e);
    s.parentId = scene.idOf(ecs::parentOf(registry, e));
    s.name = copyOf<content::Name>(registry, e);
    if (const auto* local = registry.tryGet<ecs::LocalTransform>(e)) s.local = *local;
    s.mesh = copyOf<content::MeshInstance>(registry, e);
    s.materials = copyOf<content::MaterialOverrides>(registry, e);
    s.light = copyOf<content::Light>(registry, e);
    s.camera = copyOf<content::Camera>(registry, e);
    s.sky = copyOf<content::Sky>(registry, e);
    s.fog = copyOf<content::Fog>(registry, e);
    s.rigidBody = copyOf<content::RigidBody>(registry, e);
    s.collider = copyOf<content::Collider>(registry, e);
    s.audioSource = copyOf<content::AudioSource>(registry, e);
    s.audioListener = copyOf<content::AudioListener>(registry, e);
    s.atmosphere = copyOf<content::Atmosphere>(registry, e);
    s.gameData = copyOf<content::GameData>(registry, e);
    if (const auto* member = registry.tryGet<content::SceneMember>(e)) s.sceneOrder = member->order;
    return s;
}

std::vector<EntitySnapshot> snapshotSubtree(EditorScene& scene, ecs::Entity root) {
    std::vector<EntitySnapshot> out;
    out.push_back(snapshotEntity(scene, root));
    for (ecs::Entity e : ecs::descendantsOf(scene.registry(), root)) {
        out.push_back(snapshotEntity(scene, e));
    }
    return out;
}

ecs::Entity restoreEntity(EditorScene& scene, const EntitySnapshot& s) {
    ecs::Registry& registry = scene.registry();
    ecs::Entity e = registry.create();
    scene.bind(e, s.id);
    emplaceIf(registry, e, s.name);
    registry.emplace<ecs::LocalTransform>(e, s.local);
    registry.emplace<ecs::WorldTransform>(e);
    emplaceIf(registry, e, s.mesh);
    emplaceIf(registry, e, s.materials);
    emplaceIf(registry, e, s.light);
    emplaceIf(registry, e, s.camera);
    emplaceIf(registry, e, s.sky);
    emplaceIf(registry, e, s.fog);
    emplaceIf(registry, e, s.rigidBody);
    emplaceIf(registry, e, s.collider);
    emplaceIf(registry, e, s.audioSource);
    emplaceIf(registry, e, s.audioListener);
    emplaceIf(registry, e, s.atmosphere);
    emplaceIf(registry, e, s.gameData);
    registry.emplace<content::SceneMember>(e, content::SceneMember{s.sceneOrder});
    if (ecs::Entity parent = scene.find(s.parentId); parent != ecs::kNullEntity) {
        (void)ecs::setParent(registry, e, parent);
    }
    return e;
}

}  // namespace candela::editor
