#include "model/material_editing.h"

#include "candela/content/components/mesh_instance.h"
#include "candela/content/components/scene_components.h"
#include "candela/content/model.h"
#include "model/editor_scene.h"
#include "model/set_component_command.h"

namespace candela::editor {

namespace {

const content::Mesh* meshOf(EditorScene& scene, ecs::Entity e) {
    if (!scene.registry().valid(e)) return nullptr;
    const auto* instance = scene.registry().tryGet<content::MeshInstance>(e);
    if (!instance || !instance->model || instance->mesh < 0 ||
        size_t(instance->mesh) >= instance->model->meshes.size()) {
        return nullptr;
    }
    return &instance->model->meshes[size_t(instance->mesh)];
}

}  // namespace

uint32_t primitiveCount(EditorScene& scene, ecs::Entity e) {
    const content::Mesh* mesh = meshOf(scene, e);
    return mesh ? uint32_t(mesh->primitives.size()) : 0u;
}

content::Material effectiveMaterial(EditorScene& scene, ecs::Entity e, uint32_t primitive) {
    if (const auto* overrides = scene.registry().tryGet<content::MaterialOverrides>(e)) {
        for (const content::MaterialOverride& o : overrides->overrides) {
            if (o.primitive == primitive) return o.material;
        }
    }
    const content::Mesh* mesh = meshOf(scene, e);
    if (!mesh || primitive >= mesh->primitives.size()) return {};
    const content::Model& model = *scene.registry().get<content::MeshInstance>(e).model;
    const int32_t index = mesh->primitives[primitive].material;
    if (index < 0 || size_t(index) >= model.materials.size()) return {};  // glTF default
    return model.materials[size_t(index)];
}

std::unique_ptr<EditCommand> setMaterial(EditorScene& scene, ecs::Entity e, uint32_t primitive,
                                         const content::Material& material) {
    if (primitive >= primitiveCount(scene, e)) return nullptr;
    content::MaterialOverrides overrides;
    if (const auto* current = scene.registry().tryGet<content::MaterialOverrides>(e)) {
        overrides = *current;
    }
    bool found = false;
    for (content::MaterialOverride& o : overrides.overrides) {
        if (o.primitive == primitive) {
            o.material = material;
            found = true;
        }
    }
    if (!found) overrides.overrides.push_back({primitive, material});
    return setComponent<content::MaterialOverrides>(scene, e, overrides, "Edit Material");
}

}  // namespace candela::editor
