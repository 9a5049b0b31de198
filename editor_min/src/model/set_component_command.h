#pragma once
// Replaces one component's value (a rename, a light, transform, material or camera edit).
// registry.replace marks the component changed, which is what the renderer's change detection
// (LightTable, material overrides, transform propagation) looks at.
#include <memory>
#include <string>

#include "model/edit_command.h"
#include "model/editor_scene.h"

namespace candela::editor {

template <class T>
class SetComponentCommand final : public EditCommand {
public:
    SetComponentCommand(uint64_t id, T before, T after, std::string label)
        : id_(id), before_(std::move(before)), after_(std::move(after)), label_(std::move(label)) {}

    std::string label() const override { return label_; }
    bool apply(EditorScene& scene) override { return write(scene, after_); }
    void revert(EditorScene& scene) override { (void)write(scene, before_); }
    bool absorb(const EditCommand& next) override {
        const auto* same = dynamic_cast<const SetComponentCommand<T>*>(&next);
        if (!same || same->id_ != id_) return false;
        after_ = same->after_;
        return true;
    }

private:
    bool write(EditorScene& scene, const T& value) {
        ecs::Entity e = scene.find(id_);
        if (e == ecs::kNullEntity || !scene.registry().template has<T>(e)) return false;
        scene.registry().template replace<T>(e, value);
        return true;
    }

    uint64_t id_;
    T before_;
    T after_;
    std::string label_;
};

// The command setting `e`'s T to `after` (its current value is what undo restores); null when
// `e` has no T.
template <class T>
std::unique_ptr<EditCommand> setComponent(EditorScene& scene, ecs::Entity e, T after,
                                          std::string label) {
    const T* before = scene.registry().valid(e) ? scene.registry().template tryGet<T>(e) : nullptr;
    if (!before) return nullptr;
    return std::make_unique<SetComponentCommand<T>>(scene.idOf(e), *before, std::move(after),
                                                    std::move(label));
}

}  // namespace candela::editor
