#include "model/structure_commands.h"

#include <unordered_map>
#include <vector>

#include "candela/ecs/hierarchy.h"
#include "model/editor_scene.h"
#include "model/entity_snapshot.h"

namespace candela::editor {

namespace {

// Recreates snapshots (parents first) or destroys the subtree they describe.
class SubtreeCommand : public EditCommand {
public:
    SubtreeCommand(std::vector<EntitySnapshot> subtree, std::string label)
        : subtree_(std::move(subtree)), label_(std::move(label)) {}
    std::string label() const override { return label_; }

protected:
    bool restore(EditorScene& scene) {
        if (subtree_.empty() || scene.find(subtree_.front().id) != ecs::kNullEntity) return false;
        for (const EntitySnapshot& s : subtree_)
            restoreEntity(scene, s);
        return true;
    }
    bool destroy(EditorScene& scene) {
        ecs::Entity root = subtree_.empty() ? ecs::kNullEntity : scene.find(subtree_.front().id);
        if (root == ecs::kNullEntity) return false;
        for (const EntitySnapshot& s : subtree_)
            scene.unbind(s.id);
        ecs::destroyWithDescendants(scene.registry(), root);
        return true;
    }

    std::vector<EntitySnapshot> subtree_;
    std::string label_;
};

class DeleteCommand final : public SubtreeCommand {
public:
    using SubtreeCommand::SubtreeCommand;
    bool apply(EditorScene& scene) override {
        // Descendants created since the snapshot (none through this stack) are snapshotted
        // again so undo restores exactly what was deleted.
        if (ecs::Entity root = scene.find(subtree_.front().id); root != ecs::kNullEntity) {
            subtree_ = snapshotSubtree(scene, root);
        }
        const bool wasSelected = isInSubtree(scene.selectedId());
        if (!destroy(scene)) return false;
        if (wasSelected) scene.selectId(0);
        return true;
    }
    void revert(EditorScene& scene) override { (void)restore(scene); }

private:
    bool isInSubtree(uint64_t id) const {
        for (const EntitySnapshot& s : subtree_) {
            if (s.id == id) return true;
        }
        return false;
    }
};

class InsertCommand final : public SubtreeCommand {
public:
    using SubtreeCommand::SubtreeCommand;
    bool apply(EditorScene& scene) override { return restore(scene); }
    void revert(EditorScene& scene) override {
        if (scene.selectedId() == subtree_.front().id) scene.selectId(0);
        (void)destroy(scene);
    }
};

class ReparentCommand final : public EditCommand {
public:
    ReparentCommand(uint64_t child, uint64_t oldParent, uint64_t newParent)
        : child_(child), oldParent_(oldParent), newParent_(newParent) {}
    std::string label() const override { return "Reparent"; }
    bool apply(EditorScene& scene) override { return link(scene, newParent_); }
    void revert(EditorScene& scene) override { (void)link(scene, oldParent_); }

private:
    bool link(EditorScene& scene, uint64_t parentId) {
        ecs::Entity child = scene.find(child_);
        ecs::Entity parent = parentId ? scene.find(parentId) : ecs::kNullEntity;
        if (child == ecs::kNullEntity || (parentId && parent == ecs::kNullEntity)) return false;
        if (ecs::setParent(scene.registry(), child, parent) != ecs::ReparentResult::Ok) {
            return false;
        }
        // The world transform now composes with a different parent.
        scene.registry().markChanged<ecs::LocalTransform>(child);
        return true;
    }

    uint64_t child_;
    uint64_t oldParent_;
    uint64_t newParent_;
};

}  // namespace

CreateEntityCommand::CreateEntityCommand(EditorScene& scene, ecs::Entity parent, std::string name,
                                         std::optional<content::Light> light)
    : id_(scene.newId()),
      parentId_(scene.idOf(parent)),
      order_(scene.newSceneOrder()),
      name_(std::move(name)),
      light_(std::move(light)) {}

bool CreateEntityCommand::apply(EditorScene& scene) {
    if (scene.find(id_) != ecs::kNullEntity) return false;
    EntitySnapshot s;
    s.id = id_;
    s.parentId = parentId_;
    s.name = content::Name{name_};
    s.light = light_;
    s.sceneOrder = order_;
    restoreEntity(scene, s);
    return true;
}

void CreateEntityCommand::revert(EditorScene& scene) {
    if (ecs::Entity e = scene.find(id_); e != ecs::kNullEntity) {
        if (scene.selectedId() == id_) scene.selectId(0);
        scene.unbind(id_);
        scene.registry().destroy(e);
    }
}

std::unique_ptr<EditCommand> duplicateEntity(EditorScene& scene, ecs::Entity source,
                                             uint64_t* createdId) {
    if (scene.idOf(source) == 0) return nullptr;
    std::vector<EntitySnapshot> subtree = snapshotSubtree(scene, source);
    // New ids and scene orders, parents remapped inside the copy; the root keeps its parent.
    std::unordered_map<uint64_t, uint64_t> newIdOf;
    uint32_t order = scene.newSceneOrder();
    for (EntitySnapshot& s : subtree) {
        const uint64_t copyId = scene.newId();
        newIdOf[s.id] = copyId;
        s.id = copyId;
        if (auto it = newIdOf.find(s.parentId); it != newIdOf.end()) s.parentId = it->second;
        s.sceneOrder = order++;
    }
    std::string name = scene.displayName(source) + " copy";
    subtree.front().name = content::Name{name};
    if (createdId) *createdId = subtree.front().id;
    return std::make_unique<InsertCommand>(std::move(subtree), "Duplicate " + name);
}

std::unique_ptr<EditCommand> deleteEntity(EditorScene& scene, ecs::Entity e) {
    if (scene.idOf(e) == 0) return nullptr;
    return std::make_unique<DeleteCommand>(snapshotSubtree(scene, e),
                                           "Delete " + scene.displayName(e));
}

std::unique_ptr<EditCommand> reparentEntity(EditorScene& scene, ecs::Entity child,
                                            ecs::Entity parent) {
    if (scene.idOf(child) == 0) return nullptr;
    if (parent != ecs::kNullEntity && scene.idOf(parent) == 0) return nullptr;
    return std::make_unique<ReparentCommand>(
        scene.idOf(child), scene.idOf(ecs::parentOf(scene.registry(), child)), scene.idOf(parent));
}

}  // namespace candela::editor
