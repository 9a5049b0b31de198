#pragma once
// Sets, adds or removes one component (a rename, a light, transform, material or camera edit,
// "Add Light"). Writes go through registry.emplace/remove, which mark the component changed or
// fire the add/remove hooks: what the renderer's change detection (LightTable, material
// overrides, transform propagation) looks at, so edits show on the next frame.
#include <memory>
#include <optional>
#include <string>

#include "model/edit_command.h"
#include "model/editor_scene.h"

namespace candela::editor {

template <class T>
class SetComponentCommand final : public EditCommand {
public:
    // nullopt: the entity does not have T (before: undo removes it; after: apply removes it).
    SetComponentCommand(uint64_t id, std::optional<T> before, std::optional<T> after,
                        std::string label)
        : id_(id), before_(std::move(before)), after_(std::move(after)), label_(std::move(label)) {}

    std::string label() const override { return label_; }
    bool apply(EditorScene& scene) override { return write(scene, after_); }
    void revert(EditorScene& scene) override { (void)write(scene, before_); }
    bool absorb(const EditCommand& next) override {
        const auto* same = dynamic_cast<const SetComponentCommand<T>*>(&next);
        if (!same || same->id_ != id_ || !same->after_ || !after_) return false;
        after_ = same->after_;
        return true;
    }

private:
    bool write(EditorScene& scene, const std::optional<T>& value) {
        ecs::Entity e = scene.find(id_);
        if (e == ecs::kNullEntity) return false;
        if (value) {
            scene.registry().template emplace<T>(e, *value);
        } else {
            scene.registry().template remove<T>(e);
        }
        return true;
    }

    uint64_t id_;
    std::optional<T> before_;
    std::optional<T> after_;
    std::string label_;
};

// The command giving `e` the component value `after` (nullopt: removing it); undo restores
// what `e` has now. Null when `e` is not an editor entity.
template <class T>
std::unique_ptr<EditCommand> changeComponent(EditorScene& scene, ecs::Entity e,
                                             std::optional<T> after, std::string label) {
    if (scene.idOf(e) == 0) return nullptr;
    const T* current = scene.registry().template tryGet<T>(e);
    std::optional<T> before = current ? std::optional<T>(*current) : std::nullopt;
    return std::make_unique<SetComponentCommand<T>>(scene.idOf(e), std::move(before),
                                                    std::move(after), std::move(label));
}

// Sets (or adds) `e`'s T.
template <class T>
std::unique_ptr<EditCommand> setComponent(EditorScene& scene, ecs::Entity e, T after,
                                          std::string label) {
    return changeComponent<T>(scene, e, std::optional<T>(std::move(after)), std::move(label));
}

// Removes `e`'s T (null when it has none).
template <class T>
std::unique_ptr<EditCommand> removeComponent(EditorScene& scene, ecs::Entity e, std::string label) {
    if (!scene.registry().valid(e) || !scene.registry().template has<T>(e)) return nullptr;
    return changeComponent<T>(scene, e, std::nullopt, std::move(label));
}

}  // namespace candela::editor
