#pragma once
// Everything the editor knows about an entity, as values: what delete keeps for undo and what
// duplicate copies. Restoring recreates the entity with the same EditorId and parent.
#include <cstdint>
#include <optional>
#include <vector>

#include "candela/content/components/atmosphere.h"
#include "candela/content/components/audio_listener.h"
#include "candela/content/components/audio_source.h"
#include "candela/content/components/camera.h"
#include "candela/content/components/collider.h"
#include "candela/content/components/fog.h"
#include "candela/content/components/light.h"
#include "candela/content/components/mesh_instance.h"
#include "candela/content/components/name.h"
#include "candela/content/components/rigid_body.h"
#include "candela/content/components/scene_components.h"
#include "candela/content/components/sky.h"
#include "candela/ecs/entity.h"
#include "candela/ecs/transform.h"

namespace candela::editor {

class EditorScene;

struct EntitySnapshot {
    uint64_t id = 0;
    uint64_t parentId = 0;  // 0: a root
    std::optional<content::Name> name;
    ecs::LocalTransform local;
    std::optional<content::MeshInstance> mesh;
    std::optional<content::MaterialOverrides> materials;
    std::optional<content::Light> light;
    std::optional<content::Camera> camera;
    std::optional<content::Sky> sky;
    std::optional<content::Fog> fog;
    std::optional<content::RigidBody> rigidBody;
    std::optional<content::Collider> collider;
    std::optional<content::AudioSource> audioSource;
    std::optional<content::AudioListener> audioListener;
    std::optional<content::Atmosphere> atmosphere;
    std::optional<content::GameData> gameData;
    uint32_t sceneOrder = 0;
};

EntitySnapshot snapshotEntity(EditorScene& scene, ecs::Entity e);
// `root` and its descendants, parents before children.
std::vector<EntitySnapshot> snapshotSubtree(EditorScene& scene, ecs::Entity root);
// Creates the entity with the snapshot's id and components and links it under its parent
// (which must exist already, or it becomes a root).
ecs::Entity restoreEntity(EditorScene& scene, const EntitySnapshot& snapshot);

}  // namespace candela::editor
