#include "model/property_edits.h"

#include <algorithm>
#include <functional>
#include <map>

#include "candela/content/components/camera.h"
#include "candela/content/components/light.h"
#include "candela/content/light_types.h"
#include "candela/ecs/transform.h"
#include "model/edit_validation.h"
#include "model/editor_scene.h"
#include "model/material_editing.h"
#include "model/set_component_command.h"

namespace candela::editor {

namespace {

using Values = std::vector<float>;

template <class T>
struct Field {
    size_t count;
    std::function<void(T&, const Values&)> set;
};

template <class T>
const std::map<std::string, Field<T>>& fields();

// The fields of the light type table (content/light_types.h), under their scene-file names.
template <>
const std::map<std::string, Field<content::Light>>& fields() {
    using L = content::Light;
    static const std::map<std::string, Field<L>> table = [] {
        std::map<std::string, Field<L>> out;
        for (const content::LightFieldInfo& f : content::kLightFieldTable) {
            if (f.channels) {
                out[f.name] = {3, [member = f.channels](L& l, const Values& v) {
                                   l.*member = {v[0], v[1], v[2]};
                               }};
            } else {
                out[f.name] = {1, [member = f.scalar](L& l, const Values& v) { l.*member = v[0]; }};
            }
        }
        // The shadow flag: any non-zero value casts.
        out[content::kCastShadowsKey] = {1,
                                         [](L& l, const Values& v) { l.castShadows = v[0] != 0; }};
        return out;
    }();
    return table;
}

template <>
const std::map<std::string, Field<content::Camera>>& fields() {
    using C = content::Camera;
    static const std::map<std::string, Field<C>> table = {
        {"aperture", {1, [](C& c, const Values& v) { c.aperture = v[0]; }}},
        {"shutterSeconds", {1, [](C& c, const Values& v) { c.shutterSeconds = v[0]; }}},
        {"iso", {1, [](C& c, const Values& v) { c.iso = v[0]; }}},
        {"manualEv100", {1, [](C& c, const Values& v) { c.manualEv100 = v[0]; }}},
        {"exposureCompensation", {1, [](C& c, const Values& v) { c.exposureCompensation = v[0]; }}},
        {"verticalFov", {1, [](C& c, const Values& v) { c.verticalFov = v[0]; }}},
    };
    return table;
}

template <>
const std::map<std::string, Field<ecs::LocalTransform>>& fields() {
    using T = ecs::LocalTransform;
    static const std::map<std::string, Field<T>> table = {
        {"position",
         {3,
          [](T& t, const Values& v) {
              t.position = {v[0], v[1], v[2]};
          }}},
        {"scale",
         {3,
          [](T& t, const Values& v) {
              t.scale = {v[0], v[1], v[2]};
          }}},
        {"rotation",
         {4,
          [](T& t, const Values& v) {
              t.rotation = {v[0], v[1], v[2], v[3]};
          }}},
    };
    return table;
}

template <>
const std::map<std::string, Field<content::Material>>& fields() {
    using M = content::Material;
    static const std::map<std::string, Field<M>> table = {
        {"baseColor",
         {4,
          [](M& m, const Values& v) {
              m.baseColorFactor = {v[0], v[1], v[2], v[3]};
          }}},
        {"metallic", {1, [](M& m, const Values& v) { m.metallicFactor = v[0]; }}},
        {"roughness", {1, [](M& m, const Values& v) { m.roughnessFactor = v[0]; }}},
        {"specular", {1, [](M& m, const Values& v) { m.specular = v[0]; }}},
        // [0, 1], 1 none: clamped with a notice by the shared rules (checkEdit).
        {"cavity", {1, [](M& m, const Values& v) { m.cavity = v[0]; }}},
        {"anisotropy", {1, [](M& m, const Values& v) { m.anisotropyStrength = v[0]; }}},
        {"anisotropyRotation", {1, [](M& m, const Values& v) { m.anisotropyRotation = v[0]; }}},
        {"clearcoat", {1, [](M& m, const Values& v) { m.clearcoatFactor = v[0]; }}},
        {"clearcoatRoughness",
         {1, [](M& m, const Values& v) { m.clearcoatRoughnessFactor = v[0]; }}},
    };
    return table;
}

template <class T>
const Field<T>* lookup(const std::string& name, const Values& values, std::string& error) {
    auto it = fields<T>().find(name);
    if (it == fields<T>().end()) return nullptr;
    if (values.size() != it->second.count) {
        error = "expects " + std::to_string(it->second.count) + " value(s), got " +
                std::to_string(values.size());
        return nullptr;
    }
    return &it->second;
}

// Applies the shared rules: false with `error` when refused; `notice` gets what was clamped.
template <class T>
bool accept(T& value, std::string& error, std::string* notice) {
    EditCheck check = checkEdit(value);
    if (!check.accepted) {
        error = check.notice;
        return false;
    }
    if (notice) *notice = check.notice;
    return true;
}

template <class T>
std::unique_ptr<EditCommand> componentEdit(EditorScene& scene, ecs::Entity e,
                                           const std::string& component, const std::string& name,
                                           const Values& values, std::string& error,
                                           std::string* notice) {
    const Field<T>* field = lookup<T>(name, values, error);
    if (!field) {
        if (error.empty()) error = "unknown property";
        return nullptr;
    }
    const T* current = scene.registry().tryGet<T>(e);
    if (!current) {
        error = "the entity has no " + component;
        return nullptr;
    }
    T edited = *current;
    field->set(edited, values);
    if (!accept(edited, error, notice)) return nullptr;
    return setComponent<T>(scene, e, edited, "Set " + component + "." + name);
}

}  // namespace

std::vector<std::string> editablePropertyNames() {
    std::vector<std::string> names;
    for (const auto& [n, f] : fields<content::Light>())
        names.push_back("light." + n);
    for (const auto& [n, f] : fields<content::Camera>())
        names.push_back("camera." + n);
    for (const auto& [n, f] : fields<ecs::LocalTransform>())
        names.push_back("transform." + n);
    for (const auto& [n, f] : fields<content::Material>())
        names.push_back("material." + n);
    return names;
}

std::unique_ptr<EditCommand> propertyEdit(EditorScene& scene, ecs::Entity e,
                                          const std::string& property, const Values& values,
                                          std::string& error, std::string* notice) {
    error.clear();
    if (notice) notice->clear();
    std::unique_ptr<EditCommand> command;
    if (scene.idOf(e) == 0) {
        error = "no entity selected";
        return nullptr;
    }
    const size_t dot = property.find('.');
    const std::string component = property.substr(0, dot);
    const std::string name = dot == std::string::npos ? std::string() : property.substr(dot + 1);
    if (component == "light") {
        command = componentEdit<content::Light>(scene, e, component, name, values, error, notice);
    } else if (component == "camera") {
        command = componentEdit<content::Camera>(scene, e, component, name, values, error, notice);
    } else if (component == "transform") {
        command =
            componentEdit<ecs::LocalTransform>(scene, e, component, name, values, error, notice);
    } else if (component == "material") {
        const Field<content::Material>* field = lookup<content::Material>(name, values, error);
        if (!field) {
            if (error.empty()) error = "unknown property";
        } else if (primitiveCount(scene, e) == 0) {
            error = "the entity has no loaded mesh";
        } else {
            content::Material material = effectiveMaterial(scene, e, 0);
            field->set(material, values);
            if (accept(material, error, notice)) command = setMaterial(scene, e, 0, material);
        }
    } else {
        error = "unknown property";
    }
    if (!command && !error.empty()) error = property + ": " + error;
    return command;
}

}  // namespace candela::editor
