#include "model/editor_scene.h"

#include <algorithm>

#include "candela/content/components/name.h"
#include "candela/content/components/scene_components.h"
#include "candela/ecs/hierarchy.h"
#include "candela/ecs/transform.h"
#include "model/editor_id.h"
#include "model/scene_saving.h"

namespace candela::editor {

EditorScene::EditorScene(ecs::Registry& registry, std::filesystem::path sourcePath)
    : registry_(registry), sourcePath_(std::move(sourcePath)) {
    adoptEntities();
}

void EditorScene::adoptEntities() {
    std::vector<ecs::Entity> all;
    registry_.forEachEntity([&](ecs::Entity e) { all.push_back(e); });
    // Entities loaded from a scene file keep their order; the rest (a glTF's nodes, viewing
    // defaults) follow in creation order.
    std::sort(all.begin(), all.end(),
              [](ecs::Entity a, ecs::Entity b) { return a.index() < b.index(); });
    for (ecs::Entity e : all) {
        if (!registry_.has<EditorId>(e)) bind(e, newId());
        if (!registry_.has<content::SceneMember>(e)) {
            registry_.emplace<content::SceneMember>(e, content::SceneMember{newSceneOrder()});
        }
        if (!registry_.has<ecs::LocalTransform>(e)) registry_.emplace<ecs::LocalTransform>(e);
        if (!registry_.has<ecs::WorldTransform>(e)) registry_.emplace<ecs::WorldTransform>(e);
    }
}

uint64_t EditorScene::idOf(ecs::Entity e) const {
    if (!registry_.valid(e)) return 0;
    const EditorId* id = registry_.tryGet<EditorId>(e);
    return id ? id->value : 0;
}

ecs::Entity EditorScene::find(uint64_t id) const {
    auto it = entityOfId_.find(id);
    if (it == entityOfId_.end() || !registry_.valid(it->second)) return ecs::kNullEntity;
    return it->second;
}

void EditorScene::bind(ecs::Entity e, uint64_t id) {
    registry_.emplace<EditorId>(e, EditorId{id});
    entityOfId_[id] = e;
    nextId_ = std::max(nextId_, id + 1);
}

void EditorScene::unbind(uint64_t id) {
    entityOfId_.erase(id);
}

uint32_t EditorScene::newSceneOrder() {
    uint32_t next = 0;
    registry_.view<const content::SceneMember>().each(
        [&](const content::SceneMember& member) { next = std::max(next, member.order + 1); });
    return next;
}

std::vector<ecs::Entity> EditorScene::childrenInOrder(ecs::Entity parent) const {
    std::vector<std::pair<uint32_t, ecs::Entity>> found;
    registry_.view<const content::SceneMember>().each(
        [&](ecs::Entity e, const content::SceneMember& member) {
            if (ecs::parentOf(registry_, e) == parent) found.push_back({member.order, e});
        });
    std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) {
        return a.first != b.first ? a.first < b.first : a.second.bits() < b.second.bits();
    });
    std::vector<ecs::Entity> out;
    out.reserve(found.size());
    for (const auto& [order, e] : found)
        out.push_back(e);
    return out;
}

ecs::Entity EditorScene::findByName(const std::string& name) const {
    ecs::Entity best = ecs::kNullEntity;
    uint32_t bestOrder = UINT32_MAX;
    registry_.view<const content::Name, const content::SceneMember>().each(
        [&](ecs::Entity e, const content::Name& n, const content::SceneMember& member) {
            if (n.value == name && member.order < bestOrder) {
                best = e;
                bestOrder = member.order;
            }
        });
    return best;
}

std::string EditorScene::displayName(ecs::Entity e) const {
    const content::Name* name = registry_.valid(e) ? registry_.tryGet<content::Name>(e) : nullptr;
    if (name && !name->value.empty()) return name->value;
    return "entity " + std::to_string(idOf(e));
}

std::string EditorScene::save(const std::filesystem::path& path, bool replaceReadOnly) {
    std::string error =
        saveEditedScene(registry_, sourcePath_, path, sceneSettings_,
                        content::AtomicWriteOptions{.replaceReadOnly = replaceReadOnly});
    if (error.empty()) {
        savedRevision_ = commands_.revision();
        settingsEdited_ = false;
    }
    return error;
}

}  // namespace candela::editor
