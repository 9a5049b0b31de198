#include "app/hierarchy_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <optional>
#include <string>

#include "candela/content/components/light.h"
#include "model/editor_scene.h"
#include "model/structure_commands.h"

namespace candela::editor {

namespace {

constexpr const char* kEntityPayload = "CANDELA_ENTITY";

// What the tree asked for this frame; run once drawing is done.
struct PendingEdit {
    std::unique_ptr<EditCommand> command;
    uint64_t selectAfter = 0;  // id to select once applied (0: keep)
};

void createMenu(EditorScene& scene, ecs::Entity parent, PendingEdit& pending) {
    auto create = [&](const char* name, std::optional<content::Light> light) {
        auto command = std::make_unique<CreateEntityCommand>(scene, parent, name, light);
        pending.selectAfter = command->createdId();
        pending.command = std::move(command);
    };
    if (ImGui::MenuItem("Empty")) create("entity", std::nullopt);
    if (ImGui::MenuItem("Point light")) create("point light", content::Light{});
    if (ImGui::MenuItem("Spot light")) {
        content::Light spot;
        spot.type = content::LightType::Spot;
        create("spot light", spot);
    }
}

void entityActions(EditorScene& scene, ecs::Entity e, PendingEdit& pending) {
    if (ImGui::BeginMenu("Create child")) {
        createMenu(scene, e, pending);
        ImGui::EndMenu();
    }
    if (ImGui::MenuItem("Duplicate", "Ctrl+D")) {
        pending.command = duplicateEntity(scene, e, &pending.selectAfter);
    }
    if (ImGui::MenuItem("Delete", "Del")) pending.command = deleteEntity(scene, e);
    if (ImGui::MenuItem("Make root")) pending.command = reparentEntity(scene, e, ecs::kNullEntity);
}

void drawNode(EditorScene& scene, ecs::Entity e, PendingEdit& pending, HierarchyLayout* layout) {
    const uint64_t id = scene.idOf(e);
    const std::vector<ecs::Entity> children = scene.childrenInOrder(e);
    ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_OpenOnArrow | ImGuiTreeNodeFlags_DefaultOpen |
                               ImGuiTreeNodeFlags_SpanAvailWidth;
    if (children.empty()) flags |= ImGuiTreeNodeFlags_Leaf;
    if (scene.selectedId() == id) flags |= ImGuiTreeNodeFlags_Selected;
    std::string label = scene.displayName(e);
    if (scene.registry().has<content::Light>(e)) label += "  (light)";
    const bool open =
        ImGui::TreeNodeEx(reinterpret_cast<void*>(uintptr_t(id)), flags, "%s", label.c_str());
    if (layout) (*layout)[id] = {ImGui::GetItemRectMin(), ImGui::GetItemRectMax()};
    if (ImGui::IsItemClicked() && !ImGui::IsItemToggledOpen()) scene.selectId(id);
    if (ImGui::BeginDragDropSource()) {
        ImGui::SetDragDropPayload(kEntityPayload, &id, sizeof(id));
        ImGui::Text("%s", scene.displayName(e).c_str());
        ImGui::EndDragDropSource();
    }
    if (ImGui::BeginDragDropTarget()) {
        if (const ImGuiPayload* payload = ImGui::AcceptDragDropPayload(kEntityPayload)) {
            uint64_t dragged = 0;
            std::memcpy(&dragged, payload->Data, sizeof(dragged));
            pending.command = reparentEntity(scene, scene.find(dragged), e);
        }
        ImGui::EndDragDropTarget();
    }
    if (ImGui::BeginPopupContextItem()) {
        scene.selectId(id);
        entityActions(scene, e, pending);
        ImGui::EndPopup();
    }
    if (open) {
        for (ecs::Entity child : children)
            drawNode(scene, child, pending, layout);
        ImGui::TreePop();
    }
}

}  // namespace

void drawHierarchyPanel(EditorScene& scene, HierarchyLayout* layout) {
    if (layout) layout->clear();
    PendingEdit pending;
    if (ImGui::Button("Create")) ImGui::OpenPopup("create");
    if (ImGui::BeginPopup("create")) {
        createMenu(scene, ecs::kNullEntity, pending);
        ImGui::EndPopup();
    }
    const ecs::Entity selected = scene.selected();
    ImGui::SameLine();
    ImGui::BeginDisabled(selected == ecs::kNullEntity);
    if (ImGui::Button("Duplicate")) {
        pending.command = duplicateEntity(scene, selected, &pending.selectAfter);
    }
    ImGui::SameLine();
    if (ImGui::Button("Delete")) pending.command = deleteEntity(scene, selected);
    ImGui::EndDisabled();
    ImGui::Separator();

    for (ecs::Entity root : scene.childrenInOrder(ecs::kNullEntity))
        drawNode(scene, root, pending, layout);

    // The free space below the tree: dropping there makes the entity a root.
    const ImVec2 rest = ImGui::GetContentRegionAvail();
    ImGui::InvisibleButton("##roots", ImVec2(std::max(rest.x, 1.0f), std::max(rest.y, 8.0f)));
    if (ImGui::IsItemClicked()) scene.selectId(0);
    if (ImGui::BeginDragDropTarget()) {
        if (const ImGuiPayload* payload = ImGui::AcceptDragDropPayload(kEntityPayload)) {
            uint64_t dragged = 0;
            std::memcpy(&dragged, payload->Data, sizeof(dragged));
            pending.command = reparentEntity(scene, scene.find(dragged), ecs::kNullEntity);
        }
        ImGui::EndDragDropTarget();
    }

    if (pending.command && scene.execute(std::move(pending.command)) && pending.selectAfter) {
        scene.selectId(pending.selectAfter);
    }
}

}  // namespace candela::editor
