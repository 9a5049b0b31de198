#pragma once
// Edits of the scene's structure: create, duplicate, delete (with descendants), reparent.
#include <memory>
#include <optional>
#include <string>

#include "candela/content/components/light.h"
#include "candela/ecs/entity.h"
#include "model/edit_command.h"

namespace candela::editor {

class EditorScene;

// A new entity named `name` under `parent` (kNullEntity: a root) at the origin, with a light
// when one is given. Executing it selects nothing; the new entity's id is createdId().
class CreateEntityCommand final : public EditCommand {
public:
    CreateEntityCommand(EditorScene& scene, ecs::Entity parent, std::string name,
                        std::optional<content::Light> light = std::nullopt);
    std::string label() const override { return "Create " + name_; }
    bool apply(EditorScene& scene) override;
    void revert(EditorScene& scene) override;
    uint64_t createdId() const { return id_; }

private:
    uint64_t id_;
    uint64_t parentId_;
    uint32_t order_;
    std::string name_;
    std::optional<content::Light> light_;
};

// Copies `source` and its descendants next to it (same parent); the copy's root is named
// "<name> copy" and its id is createdId().
std::unique_ptr<EditCommand> duplicateEntity(EditorScene& scene, ecs::Entity source,
                                             uint64_t* createdId = nullptr);

// Removes `e` and its descendants; undo brings them back with their components and links.
std::unique_ptr<EditCommand> deleteEntity(EditorScene& scene, ecs::Entity e);

// Makes `child` a child of `parent` (kNullEntity: a root), keeping its local transform.
// Applying fails (nothing recorded) when `parent` is `child` or one of its descendants.
std::unique_ptr<EditCommand> reparentEntity(EditorScene& scene, ecs::Entity child,
                                            ecs::Entity parent);

}  // namespace candela::editor
