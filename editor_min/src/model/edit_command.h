#pragma once
// One undoable edit. apply() and revert() must be exact inverses on the scene; commands name
// entities by EditorId so they stay valid when an undone delete recreates an entity.
#include <memory>
#include <string>

namespace candela::editor {

class EditorScene;

class EditCommand {
public:
    virtual ~EditCommand() = default;
    virtual std::string label() const = 0;  // for the Edit menu: "Undo Set Light"
    // Applies the edit; false when it cannot (its entity is gone, a cycle): nothing changed.
    virtual bool apply(EditorScene& scene) = 0;
    virtual void revert(EditorScene& scene) = 0;
    // Folds a later edit of the same property into this one (a slider drag is one undo step);
    // `next` has already been applied. False when it is not the same kind of edit.
    virtual bool absorb(const EditCommand& next) {
        (void)next;
        return false;
    }
};

}  // namespace candela::editor
