#pragma once
// The editor's model of the open scene, independent of any window or GPU: the registry being
// edited, stable entity ids, the selection, the undo stack and where the scene is saved.
// Every edit goes through `execute` so it can be undone; the ImGui panels only build commands.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "candela/content/scene_file.h"
#include "candela/ecs/entity.h"
#include "candela/ecs/registry.h"
#include "model/command_stack.h"

namespace candela::editor {

class EditorScene {
public:
    // `sourcePath` is the file the scene came from (a scene file or glTF); relative asset paths
    // stored in the entities are relative to its directory.
    EditorScene(ecs::Registry& registry, std::filesystem::path sourcePath);
    EditorScene(const EditorScene&) = delete;
    EditorScene& operator=(const EditorScene&) = delete;

    ecs::Registry& registry() { return registry_; }
    const std::filesystem::path& sourcePath() const { return sourcePath_; }
    // The render settings the scene file chooses ("aa", "ssr", "bloom"...: a key per row of
    // content/render_setting_table.h; unset: the preset's), edited in the inspector when
    // nothing is selected and written back by save(). They apply when the scene is next opened
    // (a setting chooses the renderer's passes, targets and shader variants).
    const content::RenderSettingChoices& sceneRenderSettings() const {
        return sceneSettings_.settings;
    }
    void setSceneRenderSettings(const content::RenderSettingChoices& settings,
                                bool edited = false) {
        sceneSettings_.settings = settings;
        if (edited) settingsEdited_ = true;
    }
    // The scene-wide "ambient_occlusion" radius and intensity (unset: none), edited in the
    // inspector when nothing is selected, sent to the renderer every frame (they show at once)
    // and written back by save().
    const std::optional<content::SceneAmbientOcclusion>& sceneAmbientOcclusion() const {
        return sceneSettings_.ambientOcclusion;
    }
    // Edits that are not undo steps (scene-wide settings are not entities); marks the scene
    // modified.
    void setSceneAmbientOcclusion(std::optional<content::SceneAmbientOcclusion> settings,
                                  bool edited = false) {
        sceneSettings_.ambientOcclusion = settings;
        if (edited) settingsEdited_ = true;
    }

    // The scene-wide "quality" preset (unset: the device's), edited in the inspector when nothing
    // is selected and written back by save(). It applies when the scene is next opened (a
    // preset chooses the renderer's passes, targets and shader variants).
    std::optional<content::QualityLevel> sceneQuality() const { return sceneSettings_.quality; }
    void setSceneQuality(std::optional<content::QualityLevel> level, bool edited = false) {
        sceneSettings_.quality = level;
        if (edited) settingsEdited_ = true;
    }

    // The opened file's layer library ("materialLayers"): what the inspector offers to add to
    // a material (each material edits its own copies), written back by save().
    const std::vector<content::MaterialLayer>& sceneMaterialLayers() const {
        return sceneSettings_.materialLayers;
    }
    void setSceneMaterialLayers(std::vector<content::MaterialLayer> layers) {
        sceneSettings_.materialLayers = std::move(layers);
    }

    // Gives every entity an EditorId and makes it a scene member (so it is saved): call after
    // loading and after anything outside the editor adds entities.
    void adoptEntities();

    // Entity ids: 0 is "none".
    uint64_t idOf(ecs::Entity e) const;
    ecs::Entity find(uint64_t id) const;  // kNullEntity when no live entity has it
    uint64_t newId() { return nextId_++; }
    // Records that `e` carries `id` (adds the EditorId component).
    void bind(ecs::Entity e, uint64_t id);
    void unbind(uint64_t id);
    uint32_t newSceneOrder();  // after every SceneMember::order in use

    // Finds an entity by its Name (the first in scene order); kNullEntity when none.
    ecs::Entity findByName(const std::string& name) const;
    // Scene members in scene order whose parent is `parent` (kNullEntity: roots).
    std::vector<ecs::Entity> childrenInOrder(ecs::Entity parent) const;
    std::string displayName(ecs::Entity e) const;

    // Selection by id, so it survives undo of a delete.
    uint64_t selectedId() const { return selected_; }
    ecs::Entity selected() const { return find(selected_); }
    void select(ecs::Entity e) { selected_ = idOf(e); }
    void selectId(uint64_t id) { selected_ = id; }

    bool execute(std::unique_ptr<EditCommand> command, uint64_t mergeKey = 0) {
        return commands_.execute(*this, std::move(command), mergeKey);
    }
    bool undo() { return commands_.undo(*this); }
    bool redo() { return commands_.redo(*this); }
    CommandStack& commands() { return commands_; }
    const CommandStack& commands() const { return commands_; }

    // True when edits were made (or undone) since the last successful save.
    bool modified() const { return commands_.revision() != savedRevision_ || settingsEdited_; }
    // Changes with every edit, undo and redo.
    uint64_t revision() const { return commands_.revision(); }
    // Writes the scene file atomically (content::saveSceneFile). Asset paths are rewritten
    // relative to `path`'s directory when it differs from the source's. Empty on success, else
    // the error naming the file. A read-only file is refused unless `replaceReadOnly`.
    std::string save(const std::filesystem::path& path, bool replaceReadOnly = false);

private:
    ecs::Registry& registry_;
    std::filesystem::path sourcePath_;
    std::unordered_map<uint64_t, ecs::Entity> entityOfId_;
    uint64_t nextId_ = 1;
    uint64_t selected_ = 0;
    CommandStack commands_;
    uint64_t savedRevision_ = 0;
    // The scene-wide settings (every field of a SceneDocument but its entities).
    content::SceneDocument sceneSettings_;
    bool settingsEdited_ = false;  // since the last save
};

}  // namespace candela::editor
