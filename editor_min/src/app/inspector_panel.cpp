#include "app/inspector_panel.h"

#include <imgui.h>
#include <imgui_internal.h>  // GetItemID (public from 1.87)
#include <imgui_stdlib.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/gtc/quaternion.hpp>
#include <string>

#include "app/render_settings_panel.h"
#include "candela/content/components/animation.h"
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
#include "candela/content/light_texture.h"
#include "candela/content/light_types.h"
#include "candela/content/model.h"
#include "candela/content/scene_file.h"
#include "candela/ecs/transform.h"
#include "candela/render/exposure.h"
#include "model/edit_validation.h"
#include "model/editor_scene.h"
#include "model/material_editing.h"
#include "model/set_component_command.h"

namespace candela::editor {

namespace {

// The layout being recorded by the current drawInspectorPanel call (null: none).
InspectorLayout* recording = nullptr;

void record(const char* label) {
    if (recording) (*recording)[label] = {ImGui::GetItemRectMin(), ImGui::GetItemRectMax()};
}

// Folds the edits of one widget on one entity into one undo step until it is released.
uint64_t mergeKey(EditorScene& scene, ecs::Entity e) {
    return (uint64_t(ImGui::GetItemID()) << 32) ^ scene.idOf(e) ^ 1u;
}

// Why the last edit was refused or clamped (shown at the bottom of the panel until the next
// accepted edit without a notice).
std::string editNotice;

// Called right after a widget: commits `value` when the widget changed it, and ends the undo
// step when the widget is released. A value typed past a widget's range (Ctrl+click) goes
// through the rules the scene loader applies: refused or clamped, with a notice.
template <class T>
void commit(EditorScene& scene, ecs::Entity e, bool changed, const T& value, const char* label) {
    record(label);
    if (changed) {
        T checked = value;
        const EditCheck check = checkEdit(checked);
        editNotice = check.notice.empty()
                         ? std::string()
                         : std::string(check.accepted ? "Clamped: " : "Refused: ") + check.notice;
        if (check.accepted) {
            scene.execute(setComponent(scene, e, checked, label), mergeKey(scene, e));
        }
    }
    if (ImGui::IsItemDeactivated()) scene.commands().closeMerge();
}

bool sameQuat(const ecs::Quat& a, const ecs::Quat& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z && a.w == b.w;
}

void drawName(EditorScene& scene, ecs::Entity e) {
    const content::Name* current = scene.registry().tryGet<content::Name>(e);
    std::string name = current ? current->value : std::string();
    const bool changed = ImGui::InputText("Name", &name);
    commit(scene, e, changed, content::Name{name}, "Rename");
}

void drawTransform(EditorScene& scene, ecs::Entity e, InspectorState& state) {
    const auto* current = scene.registry().tryGet<ecs::LocalTransform>(e);
    if (!current || !ImGui::CollapsingHeader("Transform", ImGuiTreeNodeFlags_DefaultOpen)) return;
    ecs::LocalTransform t = *current;
    commit(scene, e, ImGui::DragFloat3("Position", &t.position.x, 0.05f), t, "Move");
    if (state.eulerEntity != scene.idOf(e) || !sameQuat(state.eulerSource, t.rotation)) {
        const glm::vec3 euler = glm::degrees(
            glm::eulerAngles(glm::quat(t.rotation.w, t.rotation.x, t.rotation.y, t.rotation.z)));
        state.eulerEntity = scene.idOf(e);
        state.eulerSource = t.rotation;
        state.eulerDegrees[0] = euler.x;
        state.eulerDegrees[1] = euler.y;
        state.eulerDegrees[2] = euler.z;
    }
    const bool rotated =
        ImGui::DragFloat3("Rotation", state.eulerDegrees, 0.5f, 0.0f, 0.0f, "%.1f deg");
    if (rotated) {
        const glm::quat q(glm::radians(
            glm::vec3(state.eulerDegrees[0], state.eulerDegrees[1], state.eulerDegrees[2])));
        t.rotation = {q.x, q.y, q.z, q.w};
        state.eulerSource = t.rotation;
    }
    commit(scene, e, rotated, t, "Rotate");
    commit(scene, e, ImGui::DragFloat3("Scale", &t.scale.x, 0.01f), t, "Scale");
}

// A rect's emissive image (issue 15): the file as the scene file stores it (relative to it),
// decoded when Enter is pressed; one that cannot be read is refused with a notice naming it and
// the problem, and the light keeps its image. An empty name removes the image.
void drawLightTexture(EditorScene& scene, ecs::Entity e, content::Light l) {
    const auto current = content::findLightTexture(l.texture);
    const std::string before = current ? current->file : std::string();
    std::string file = before;
    bool changed =
        ImGui::InputText("Texture", &file, ImGuiInputTextFlags_EnterReturnsTrue) && file != before;
    if (changed && file.empty()) {
        l.texture = 0;
    } else if (changed) {
        std::string problem;
        auto image =
            content::loadLightTexture(content::resolveScenePath(scene.sourcePath(), file), problem);
        if (image) {
            l.texture = content::registerLightTexture(file, std::move(image));
        } else {
            editNotice = "Refused: light texture '" + file + "': " + problem;
            changed = false;
        }
    }
    commit(scene, e, changed, l, "Set Light Texture");
}

void drawLight(EditorScene& scene, ecs::Entity e) {
    const auto* current = scene.registry().tryGet<content::Light>(e);
    if (!current) return;
    bool open = ImGui::CollapsingHeader("Light", ImGuiTreeNodeFlags_DefaultOpen);
    if (ImGui::BeginPopupContextItem("light context")) {
        if (ImGui::MenuItem("Remove light")) {
            scene.execute(removeComponent<content::Light>(scene, e, "Remove Light"));
        }
        ImGui::EndPopup();
        return;
    }
    if (!open) return;
    content::Light l = *current;
    // Types and fields from the light type table (content/light_types.h): each type shows the
    // fields it uses, in the table's order.
    std::array<const char*, content::kLightTypeCount> types{};
    for (size_t i = 0; i < types.size(); ++i)
        types[i] = content::kLightTypeTable[i].label;
    int type = int(content::lightTypeIndex(l.type));
    const bool typeChanged = ImGui::Combo("Type", &type, types.data(), int(types.size()));
    l.type = content::kLightTypeTable[size_t(type)].type;
    commit(scene, e, typeChanged, l, "Set Light Type");
    for (const content::LightFieldInfo& f : content::kLightFieldTable) {
        if (!content::usesField(l.type, f.field)) continue;
        bool changed = false;
        switch (f.widget) {
            case content::LightFieldWidget::Color:
                changed = ImGui::ColorEdit3(f.label, (l.*f.channels).data());
                break;
            case content::LightFieldWidget::Drag:
                changed = ImGui::DragFloat(f.label, &(l.*f.scalar), f.dragSpeed, f.dragMin,
                                           f.dragMax, f.format);
                break;
            case content::LightFieldWidget::Angle:
                changed = ImGui::SliderAngle(f.label, &(l.*f.scalar), f.dragMin, f.dragMax);
                break;
        }
        commit(scene, e, changed, l, f.undoLabel);
    }
    commit(scene, e, ImGui::Checkbox("Cast shadows", &l.castShadows), l, "Set Cast Shadows");
    if (l.type == content::LightType::Rect) drawLightTexture(scene, e, l);
}

void drawCamera(EditorScene& scene, ecs::Entity e) {
    const auto* current = scene.registry().tryGet<content::Camera>(e);
    if (!current || !ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen)) return;
    content::Camera c = *current;
    commit(scene, e, ImGui::SliderAngle("Vertical FOV", &c.verticalFov, 1.0f, 170.0f), c,
           "Set FOV");
    const char* modes[] = {"Physical", "Manual"};
    int mode = int(c.exposureMode);
    const bool modeChanged = ImGui::Combo("Exposure", &mode, modes, 2);
    c.exposureMode = content::ExposureMode(mode);
    commit(scene, e, modeChanged, c, "Set Exposure Mode");
    if (c.exposureMode == content::ExposureMode::Physical) {
        commit(scene, e, ImGui::DragFloat("Aperture", &c.aperture, 0.1f, 0.5f, 64.0f, "f/%.1f"), c,
               "Set Aperture");
        float shutterInverse = c.shutterSeconds > 0.0f ? 1.0f / c.shutterSeconds : 100.0f;
        const bool shutter =
            ImGui::DragFloat("Shutter", &shutterInverse, 1.0f, 0.01f, 1.0e5f, "1/%.0f s");
        if (shutter && shutterInverse > 0.0f) c.shutterSeconds = 1.0f / shutterInverse;
        commit(scene, e, shutter, c, "Set Shutter");
        commit(scene, e, ImGui::DragFloat("ISO", &c.iso, 10.0f, 1.0f, 1.0e6f, "%.0f"), c,
               "Set ISO");
    } else {
        commit(scene, e, ImGui::DragFloat("EV100", &c.manualEv100, 0.05f, -10.0f, 30.0f), c,
               "Set EV100");
    }
    commit(
        scene, e,
        ImGui::DragFloat("Compensation", &c.exposureCompensation, 0.05f, -10.0f, 10.0f, "%.2f EV"),
        c, "Set Exposure Compensation");
    ImGui::Text("EV100 %.2f", render::ev100FromCamera(c));
}

// A participating medium (issue 17): coefficients per metre, the phase function's g, and the
// optional height falloff. Values past the loader's rules are refused or clamped by commit().
void drawFog(EditorScene& scene, ecs::Entity e) {
    const auto* current = scene.registry().tryGet<content::Fog>(e);
    if (!current) return;
    const bool open = ImGui::CollapsingHeader("Fog", ImGuiTreeNodeFlags_DefaultOpen);
    if (ImGui::BeginPopupContextItem("fog context")) {
        if (ImGui::MenuItem("Remove fog")) {
            scene.execute(removeComponent<content::Fog>(scene, e, "Remove Fog"));
        }
        ImGui::EndPopup();
        return;
    }
    if (!open) return;
    content::Fog f = *current;
    commit(scene, e, ImGui::DragFloat("Scattering", &f.scattering, 0.001f, 0.0f, 10.0f, "%.4f /m"),
           f, "Set Fog Scattering");
    commit(scene, e, ImGui::DragFloat("Absorption", &f.absorption, 0.001f, 0.0f, 10.0f, "%.4f /m"),
           f, "Set Fog Absorption");
    commit(scene, e, ImGui::SliderFloat("Anisotropy g", &f.anisotropy, -0.95f, 0.95f), f,
           "Set Fog Anisotropy");
    commit(scene, e,
           ImGui::DragFloat("Height falloff", &f.heightFalloff, 0.01f, 0.0f, 10.0f, "%.3f /m"), f,
           "Set Fog Height Falloff");
    commit(scene, e,
           ImGui::DragFloat("Base height", &f.baseHeight, 0.05f, -1.0e4f, 1.0e4f, "%.2f m"), f,
           "Set Fog Base Height");
    // Bounds: the world-space box the medium fills (none: the whole scene). A new box is
    // 10 m wide and deep and 5 m high, so that it is valid (min below max on every axis).
    bool bounded = f.bounds.has_value();
    if (ImGui::Checkbox("Bounded to a box", &bounded)) {
        if (bounded) {
            f.bounds = content::FogBounds{{-5.0f, 0.0f, -5.0f}, {5.0f, 5.0f, 5.0f}};
        } else {
            f.bounds.reset();
        }
        commit(scene, e, true, f, "Set Fog Bounds");
    }
    if (f.bounds) {
        commit(
            scene, e,
            ImGui::DragFloat3("Bounds min", f.bounds->min.data(), 0.05f, -1.0e4f, 1.0e4f, "%.2f m"),
            f, "Set Fog Bounds");
        commit(
            scene, e,
            ImGui::DragFloat3("Bounds max", f.bounds->max.data(), 0.05f, -1.0e4f, 1.0e4f, "%.2f m"),
            f, "Set Fog Bounds");
    }
}

// Opens a component's section with a context menu to remove it; false when closed or removed.
template <class T>
bool componentHeader(EditorScene& scene, ecs::Entity e, const char* title, const char* remove) {
    const bool open = ImGui::CollapsingHeader(title, ImGuiTreeNodeFlags_DefaultOpen);
    if (ImGui::BeginPopupContextItem(title)) {
        if (ImGui::MenuItem(remove)) scene.execute(removeComponent<T>(scene, e, remove));
        ImGui::EndPopup();
        return false;
    }
    return open;
}

// How the entity moves under physics (issue 46); values past the loader's rules are refused
// or clamped by commit(). The simulation's own state (velocities, sleeping) is not edited.
void drawRigidBody(EditorScene& scene, ecs::Entity e) {
    const auto* current = scene.registry().tryGet<content::RigidBody>(e);
    if (!current ||
        !componentHeader<content::RigidBody>(scene, e, "Rigid body", "Remove Rigid Body")) {
        return;
    }
    content::RigidBody b = *current;
    const char* types[] = {"Static", "Dynamic", "Kinematic"};
    int type = int(b.type);
    const bool typeChanged = ImGui::Combo("Type", &type, types, 3);
    b.type = content::BodyType(type);
    commit(scene, e, typeChanged, b, "Set Body Type");
    commit(scene, e, ImGui::DragFloat("Mass", &b.mass, 0.05f, 0.001f, 1.0e6f, "%.3f kg"), b,
           "Set Mass");
    commit(scene, e, ImGui::DragFloat("Friction", &b.friction, 0.01f, 0.0f, 2.0f), b,
           "Set Friction");
    commit(scene, e, ImGui::SliderFloat("Restitution", &b.restitution, 0.0f, 1.0f), b,
           "Set Restitution");
    commit(scene, e, ImGui::SliderFloat("Linear damping", &b.linearDamping, 0.0f, 1.0f), b,
           "Set Linear Damping");
    commit(scene, e, ImGui::SliderFloat("Angular damping", &b.angularDamping, 0.0f, 1.0f), b,
           "Set Angular Damping");
    commit(scene, e, ImGui::DragFloat("Gravity scale", &b.gravityScale, 0.01f, -10.0f, 10.0f), b,
           "Set Gravity Scale");
    commit(scene, e, ImGui::Checkbox("Can sleep", &b.canSleep), b, "Set Can Sleep");
    commit(scene, e, ImGui::Checkbox("Continuous collision", &b.continuousCollision), b,
           "Set Continuous Collision");
}

// The shape the entity collides with: sizes left unset fit the builtin mesh of the shape's
// name; a check box sets one explicitly.
void drawCollider(EditorScene& scene, ecs::Entity e) {
    const auto* current = scene.registry().tryGet<content::Collider>(e);
    if (!current || !componentHeader<content::Collider>(scene, e, "Collider", "Remove Collider")) {
        return;
    }
    content::Collider c = *current;
    const char* shapes[] = {"Sphere", "Box", "Capsule", "Cylinder", "Convex hull", "Triangle mesh"};
    int shape = int(c.shape);
    const bool shapeChanged = ImGui::Combo("Shape", &shape, shapes, 6);
    c.shape = content::ColliderShape(shape);
    commit(scene, e, shapeChanged, c, "Set Collider Shape");
    const auto optionalSize = [&](const char* label, std::optional<float>& size, float fallback) {
        bool set = size.has_value();
        if (ImGui::Checkbox(label, &set)) {
            size = set ? std::optional(fallback) : std::nullopt;
            commit(scene, e, true, c, "Set Collider Size");
        }
        if (size) {
            ImGui::SameLine();
            ImGui::PushID(label);
            commit(scene, e, ImGui::DragFloat("##size", &*size, 0.01f, 1e-3f, 1e4f, "%.3f m"), c,
                   "Set Collider Size");
            ImGui::PopID();
        }
    };
    using content::ColliderShape;
    if (c.shape == ColliderShape::Box) {
        bool set = c.halfExtents.has_value();
        if (ImGui::Checkbox("Half extents", &set)) {
            c.halfExtents =
                set ? std::optional(content::kDefaultColliderHalfExtents) : std::nullopt;
            commit(scene, e, true, c, "Set Collider Size");
        }
        if (c.halfExtents) {
            commit(scene, e,
                   ImGui::DragFloat3("##half extents", &c.halfExtents->x, 0.01f, 1e-3f, 1e4f,
                                     "%.3f m"),
                   c, "Set Collider Size");
        }
    } else if (c.shape != ColliderShape::ConvexHull && c.shape != ColliderShape::TriangleMesh) {
        optionalSize("Radius", c.radius, content::kDefaultColliderRadius);
        if (c.shape != ColliderShape::Sphere) {
            optionalSize("Height", c.height,
                         c.shape == ColliderShape::Capsule ? content::kDefaultCapsuleHeight
                                                           : content::kDefaultCylinderHeight);
        }
    }
    commit(scene, e, ImGui::Checkbox("Trigger", &c.trigger), c, "Set Trigger");
}

// The physically based sky (issue 16): the sun's time of day and place, the ground albedo and
// the aerosol haze; the rest (Earth's coefficients) is left to the scene file. Values past the
// loader's rules are refused or clamped by commit().
void drawAtmosphere(EditorScene& scene, ecs::Entity e) {
    const auto* current = scene.registry().tryGet<content::Atmosphere>(e);
    if (!current) return;
    const bool open = ImGui::CollapsingHeader("Atmosphere", ImGuiTreeNodeFlags_DefaultOpen);
    if (ImGui::BeginPopupContextItem("atmosphere context")) {
        if (ImGui::MenuItem("Remove atmosphere")) {
            scene.execute(removeComponent<content::Atmosphere>(scene, e, "Remove Atmosphere"));
        }
        ImGui::EndPopup();
        return;
    }
    if (!open) return;
    content::Atmosphere a = *current;
    commit(scene, e, ImGui::DragFloat("Time of day", &a.timeOfDay, 0.05f, -1.0f, 24.0f, "%.2f h"),
           a, "Set Atmosphere Time Of Day");
    commit(scene, e, ImGui::DragFloat("Latitude", &a.latitude, 0.5f, -90.0f, 90.0f, "%.1f deg"), a,
           "Set Atmosphere Latitude");
    commit(scene, e, ImGui::DragFloat("Day of year", &a.dayOfYear, 1.0f, 1.0f, 366.0f, "%.0f"), a,
           "Set Atmosphere Day");
    commit(scene, e, ImGui::ColorEdit3("Ground albedo", a.groundAlbedo.data()), a,
           "Set Atmosphere Ground Albedo");
    float mie = a.mieScattering * 1e6f;
    const bool haze = ImGui::DragFloat("Mie scattering", &mie, 0.05f, 0.0f, 1000.0f, "%.2f /Mm");
    a.mieScattering = mie * 1e-6f;
    commit(scene, e, haze, a, "Set Atmosphere Haze");
    commit(scene, e, ImGui::SliderFloat("Mie g", &a.mieAnisotropy, -0.95f, 0.95f), a,
           "Set Atmosphere Mie Anisotropy");
    commit(scene, e,
           ImGui::DragFloat("Solar illuminance", &a.solarIlluminance, 100.0f, 0.0f, 1.0e6f,
                            "%.0f lux"),
           a, "Set Atmosphere Solar Illuminance");
}

// Material layers (issue 21): the material's layers (copies of the scene library's, edited
// per material), adding one from the library, removing one, and the mask. Every change goes
// through `edited`, i.e. one undoable "Edit Material" command (drags merge into one step).
template <class Edited>
void drawMaterialLayers(const std::vector<content::MaterialLayer>& library, content::Material& m,
                        Edited& edited) {
    content::MaterialLayering& l = m.layering;
    const std::string title = "Layers (" + std::to_string(l.layers.size()) + ")";
    if (!ImGui::TreeNode("layers", "%s", title.c_str())) return;
    for (size_t i = 0; i < l.layers.size(); ++i) {
        content::MaterialLayer& layer = l.layers[i];
        ImGui::PushID(int(i));
        const char* channel[] = {"R", "G", "B"};
        const std::string label =
            (i == 0 ? std::string("Base")
                    : "Layer " + std::to_string(i) + " (mask " + channel[(i - 1) % 3] + ")") +
            ": " + layer.name;
        bool removed = false;
        if (ImGui::TreeNode("layer", "%s", label.c_str())) {
            edited(ImGui::ColorEdit3("Base colour", layer.baseColorFactor.data()));
            edited(ImGui::SliderFloat("Metallic", &layer.metallicFactor, 0.0f, 1.0f));
            edited(ImGui::SliderFloat("Roughness", &layer.roughnessFactor, 0.0f, 1.0f));
            edited(ImGui::SliderFloat("Specular", &layer.specular, 0.0f, 1.0f));
            edited(ImGui::SliderFloat("Normal strength", &layer.normalScale, 0.0f, 2.0f));
            edited(ImGui::DragFloat2("UV scale", layer.uvScale.data(), 0.05f, 0.01f, 256.0f));
            removed = ImGui::Button("Remove layer");
            ImGui::TreePop();
        }
        ImGui::PopID();
        if (removed) {
            l.layers.erase(l.layers.begin() + std::ptrdiff_t(i));
            edited(true);
            break;
        }
    }
    if (l.layers.size() < content::kMaxMaterialLayers && !library.empty() &&
        ImGui::BeginCombo("Add layer", "from the scene's library")) {
        for (const content::MaterialLayer& entry : library) {
            if (ImGui::Selectable(entry.name.c_str())) {
                l.layers.push_back(entry);
                edited(true);
            }
        }
        ImGui::EndCombo();
    }
    if (l.layers.size() > 1) {
        const char* sources[] = {"Texture R, G, B", "Vertex colour R, G, B"};
        int source = int(l.maskSource);
        const bool sourceChanged = ImGui::Combo("Mask", &source, sources, 2);
        l.maskSource = content::LayerMaskSource(source);
        edited(sourceChanged);
        if (l.maskSource == content::LayerMaskSource::Texture) {
            int texture = l.maskTexture.texture;
            const bool textureChanged = ImGui::InputInt("Mask texture", &texture);
            l.maskTexture.texture = std::max(texture, -1);
            edited(textureChanged);
            edited(ImGui::DragFloat2("Mask UV scale", l.maskTexture.transform.scale.data(), 0.05f,
                                     0.01f, 256.0f));
        }
    }
    ImGui::TreePop();
}

void drawMaterials(EditorScene& scene, ecs::Entity e) {
    const uint32_t primitives = primitiveCount(scene, e);
    if (primitives == 0 || !ImGui::CollapsingHeader("Material", ImGuiTreeNodeFlags_DefaultOpen)) {
        return;
    }
    for (uint32_t p = 0; p < primitives; ++p) {
        ImGui::PushID(int(p));
        content::Material m = effectiveMaterial(scene, e, p);
        const std::string title =
            "Primitive " + std::to_string(p) + (m.name.empty() ? "" : " (" + m.name + ")");
        if (primitives == 1 || ImGui::TreeNodeEx(title.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) {
            auto edited = [&](bool changed) {
                if (changed) scene.execute(setMaterial(scene, e, p, m), mergeKey(scene, e));
                if (ImGui::IsItemDeactivated()) scene.commands().closeMerge();
            };
            const char* models[] = {"Default lit", "Subsurface", "Legacy", "Unlit"};
            int model = int(m.shadingModel);
            const bool modelChanged = ImGui::Combo("Shading model", &model, models, 4);
            m.shadingModel = content::ShadingModel(model);
            edited(modelChanged);
            edited(ImGui::ColorEdit4("Base colour", m.baseColorFactor.data()));
            if (m.shadingModel == content::ShadingModel::Legacy) {
                edited(ImGui::ColorEdit3("Diffuse colour", m.diffuseColor.data()));
                edited(ImGui::ColorEdit3("Specular colour", m.specularColor.data()));
            } else if (m.shadingModel != content::ShadingModel::Unlit) {
                edited(ImGui::SliderFloat("Metallic", &m.metallicFactor, 0.0f, 1.0f));
                edited(ImGui::SliderFloat("Roughness", &m.roughnessFactor, 0.0f, 1.0f));
                edited(ImGui::SliderFloat("Specular", &m.specular, 0.0f, 1.0f));
                // UE4's Cavity: darkens the sky's light only (1: none).
                edited(ImGui::SliderFloat("Cavity", &m.cavity, 0.0f, 1.0f));
            }
            if (m.shadingModel == content::ShadingModel::Subsurface) {
                edited(ImGui::ColorEdit3("Subsurface colour", m.subsurfaceColor.data()));
                edited(ImGui::SliderFloat("Subsurface opacity", &m.subsurfaceOpacity, 0.0f, 1.0f));
            }
            edited(ImGui::ColorEdit3("Emissive", m.emissiveFactor.data()));
            if (m.shadingModel != content::ShadingModel::Unlit) {
                // KHR_materials_anisotropy and KHR_materials_clearcoat (0: off, and compiled
                // out of frames that use neither).
                edited(ImGui::SliderFloat("Anisotropy", &m.anisotropyStrength, 0.0f, 1.0f));
                edited(ImGui::SliderAngle("Anisotropy rotation", &m.anisotropyRotation));
                edited(ImGui::SliderFloat("Clear coat", &m.clearcoatFactor, 0.0f, 1.0f));
                edited(ImGui::SliderFloat("Clear coat roughness", &m.clearcoatRoughnessFactor, 0.0f,
                                          1.0f));
                drawMaterialLayers(scene.sceneMaterialLayers(), m, edited);
            }
            if (primitives > 1) ImGui::TreePop();
        }
        ImGui::PopID();
    }
}

// A glTF's animation player (on the model's root entity): the clip, play / pause, a time
// slider that scrubs (pausing playback and any crossfade), speed and looping. Scene files keep
// no player state yet, so these change the running player directly, with no undo step.
void drawAnimation(EditorScene& scene, ecs::Entity e) {
    auto* player = scene.registry().tryGet<content::AnimationPlayer>(e);
    if (!player || !player->model || player->model->animations.empty()) return;
    if (!ImGui::CollapsingHeader("Animation", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const std::vector<content::AnimationClip>& clips = player->model->animations;
    const int clip = player->clip >= 0 && player->clip < int(clips.size()) ? player->clip : -1;
    const std::string preview = clip >= 0 ? std::to_string(clip) + " " + clips[clip].name : "-";
    if (ImGui::BeginCombo("Clip", preview.c_str())) {
        for (int i = 0; i < int(clips.size()); ++i) {
            const std::string label = std::to_string(i) + " " + clips[size_t(i)].name;
            if (ImGui::Selectable(label.c_str(), i == clip)) player->play(i, player->loop);
        }
        ImGui::EndCombo();
    }
    record("Animation clip");
    if (ImGui::Button(player->playing ? "Pause" : "Play")) player->playing = !player->playing;
    record("Animation play");
    // The time the pose shows: wrapped when looping, else held at the ends.
    const float duration = clip >= 0 ? clips[size_t(clip)].duration : 0.0f;
    float shown = std::max(player->time, 0.0f);
    if (duration > 0.0f) {
        shown = player->loop ? std::fmod(shown, duration) : std::min(shown, duration);
    }
    if (ImGui::SliderFloat("Time", &shown, 0.0f, std::max(duration, 1e-3f), "%.2f s")) {
        player->time = shown;
        player->playing = false;
        player->nextClip = -1;
    }
    record("Animation time");
    ImGui::DragFloat("Speed", &player->speed, 0.01f, -4.0f, 4.0f, "%.2fx");
    ImGui::Checkbox("Loop", &player->loop);
}

// A sound the entity plays (issue 47). The clip is a path as the scene loaded it (absolute;
// saving writes it relative to the scene file); the editor does not play sounds.
void drawAudioSource(EditorScene& scene, ecs::Entity e) {
    const auto* current = scene.registry().tryGet<content::AudioSource>(e);
    if (!current ||
        !componentHeader<content::AudioSource>(scene, e, "Audio source", "Remove Audio Source")) {
        return;
    }
    content::AudioSource a = *current;
    if (ImGui::InputText("Clip", &a.clip, ImGuiInputTextFlags_EnterReturnsTrue))
        commit(scene, e, true, a, "Set Audio Clip");
    commit(scene, e, ImGui::DragFloat("Gain", &a.gain, 0.01f, 0.0f, 10.0f), a, "Set Audio Gain");
    commit(scene, e, ImGui::DragFloat("Pitch", &a.pitch, 0.01f, 0.05f, 4.0f), a, "Set Audio Pitch");
    commit(scene, e, ImGui::Checkbox("Loop", &a.loop), a, "Set Audio Loop");
    commit(scene, e, ImGui::Checkbox("Spatial", &a.spatial), a, "Set Audio Spatial");
    bool playing = a.state != content::PlaybackState::Stopped;
    if (ImGui::Checkbox("Plays on start", &playing)) {
        a.state = playing ? content::PlaybackState::Playing : content::PlaybackState::Stopped;
        commit(scene, e, true, a, "Set Audio Plays On Start");
    }
    if (a.spatial) {
        commit(scene, e,
               ImGui::DragFloat("Min distance", &a.minDistance, 0.05f, 0.01f, 1.0e4f, "%.2f m"), a,
               "Set Audio Distance");
        commit(scene, e,
               ImGui::DragFloat("Max distance", &a.maxDistance, 0.5f, 0.01f, 1.0e5f, "%.1f m"), a,
               "Set Audio Distance");
        commit(scene, e, ImGui::DragFloat("Rolloff", &a.rolloff, 0.01f, 0.0f, 10.0f), a,
               "Set Audio Rolloff");
    }
}

void drawAudioListener(EditorScene& scene, ecs::Entity e) {
    const auto* current = scene.registry().tryGet<content::AudioListener>(e);
    if (!current || !componentHeader<content::AudioListener>(scene, e, "Audio listener",
                                                             "Remove Audio Listener")) {
        return;
    }
    content::AudioListener l = *current;
    commit(scene, e, ImGui::DragFloat("Master gain", &l.gain, 0.01f, 0.0f, 10.0f), l,
           "Set Listener Gain");
}

void drawAddComponent(EditorScene& scene, ecs::Entity e) {
    if (ImGui::Button("Add component")) ImGui::OpenPopup("add component");
    if (ImGui::BeginPopup("add component")) {
        if (!scene.registry().has<content::Light>(e) && ImGui::MenuItem("Light")) {
            scene.execute(setComponent(scene, e, content::Light{}, "Add Light"));
        }
        if (!scene.registry().has<content::Camera>(e) && ImGui::MenuItem("Camera")) {
            scene.execute(setComponent(scene, e, content::Camera{}, "Add Camera"));
        }
        if (!scene.registry().has<content::Fog>(e) && ImGui::MenuItem("Fog")) {
            scene.execute(setComponent(scene, e, content::Fog{}, "Add Fog"));
        }
        if (!scene.registry().has<content::Atmosphere>(e) && ImGui::MenuItem("Atmosphere")) {
            scene.execute(setComponent(scene, e, content::Atmosphere{}, "Add Atmosphere"));
        }
        if (!scene.registry().has<content::Collider>(e) && ImGui::MenuItem("Collider")) {
            scene.execute(setComponent(scene, e, content::Collider{}, "Add Collider"));
        }
        if (!scene.registry().has<content::RigidBody>(e) && ImGui::MenuItem("Rigid body")) {
            scene.execute(setComponent(scene, e, content::RigidBody{}, "Add Rigid Body"));
        }
        if (!scene.registry().has<content::AudioSource>(e) && ImGui::MenuItem("Audio source")) {
            scene.execute(setComponent(scene, e, content::AudioSource{.clip = "sounds/sound.wav"},
                                       "Add Audio Source"));
        }
        if (!scene.registry().has<content::AudioListener>(e) && ImGui::MenuItem("Audio listener")) {
            scene.execute(setComponent(scene, e, content::AudioListener{}, "Add Audio Listener"));
        }
        ImGui::EndPopup();
    }
}

}  // namespace

namespace {

// The scene file's "quality": the preset its frames render at (unset: the device's).
void drawSceneQuality(EditorScene& scene) {
    if (!ImGui::CollapsingHeader("Quality", ImGuiTreeNodeFlags_DefaultOpen)) return;
    static constexpr const char* kLevels[] = {"device's", "low", "medium", "high", "ultra"};
    const std::optional<content::QualityLevel> level = scene.sceneQuality();
    int choice = level ? int(*level) + 1 : 0;
    if (ImGui::Combo("Preset", &choice, kLevels, 5)) {
        scene.setSceneQuality(
            choice == 0 ? std::nullopt
                        : std::optional<content::QualityLevel>(content::kQualityLevels[choice - 1]),
            true);
    }
    record("Quality preset");
    ImGui::TextDisabled("Applies when the scene is next opened");
}

// Ambient occlusion of the sky's light (the scene file's "ambient_occlusion": its mode is a
// render setting, the "ambient_occlusion" row of the render settings).
void drawSceneAmbientOcclusion(EditorScene& scene) {
    if (!ImGui::CollapsingHeader("Ambient occlusion", ImGuiTreeNodeFlags_DefaultOpen)) return;
    content::SceneAmbientOcclusion ao =
        scene.sceneAmbientOcclusion().value_or(content::SceneAmbientOcclusion{});
    bool changed = ImGui::DragFloat("Radius (m)", &ao.radius, 0.01f, 0.05f, 10.0f);
    record("AO radius");
    changed |= ImGui::SliderFloat("Intensity", &ao.intensity, 0.0f, 1.0f);
    record("AO intensity");
    ao.radius = std::clamp(ao.radius, 0.05f, 10.0f);  // the same rules as the scene loader
    ao.intensity = std::clamp(ao.intensity, 0.0f, 1.0f);
    if (changed) scene.setSceneAmbientOcclusion(ao, true);
}

}  // namespace

// Scene-wide settings, shown when no entity is selected.
void drawSceneSettings(EditorScene& scene) {
    drawSceneQuality(scene);
    drawSceneAmbientOcclusion(scene);
    drawSceneRenderSettings(scene, recording);
}

void drawInspectorPanel(EditorScene& scene, InspectorState& state) {
    const ecs::Entity e = scene.selected();
    if (e == ecs::kNullEntity) {
        ImGui::TextDisabled("Nothing selected");
        recording = state.layout;
        if (recording) recording->clear();
        ImGui::PushItemWidth(-110.0f);
        drawSceneSettings(scene);
        ImGui::PopItemWidth();
        recording = nullptr;
        return;
    }
    recording = state.layout;
    if (recording) recording->clear();
    ImGui::PushID(int(scene.idOf(e)));
    ImGui::PushItemWidth(-110.0f);
    drawName(scene, e);
    drawTransform(scene, e, state);
    // Each section re-reads its component: an edit above may have replaced it this frame.
    if (scene.registry().valid(e)) drawLight(scene, e);
    if (scene.registry().valid(e)) drawCamera(scene, e);
    if (scene.registry().valid(e)) drawFog(scene, e);
    if (scene.registry().valid(e)) drawAtmosphere(scene, e);
    if (scene.registry().valid(e)) drawRigidBody(scene, e);
    if (scene.registry().valid(e)) drawCollider(scene, e);
    if (scene.registry().valid(e)) drawAudioSource(scene, e);
    if (scene.registry().valid(e)) drawAudioListener(scene, e);
    if (scene.registry().valid(e)) drawMaterials(scene, e);
    if (scene.registry().valid(e)) drawAnimation(scene, e);
    if (scene.registry().valid(e)) drawAddComponent(scene, e);
    if (!editNotice.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(255, 170, 60, 255));
        ImGui::TextWrapped("%s", editNotice.c_str());
        ImGui::PopStyleColor();
    }
    ImGui::PopItemWidth();
    ImGui::PopID();
    recording = nullptr;
}

}  // namespace candela::editor
