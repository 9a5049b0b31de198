#include "candela/content/builtin_meshes.h"

#include <array>
#include <utility>

#include "candela/content/procedural_mesh.h"

namespace candela::content {

namespace {

constexpr std::array<std::pair<BuiltinMesh, std::string_view>, 3> kNames{
    {{BuiltinMesh::Plane, "plane"}, {BuiltinMesh::Box, "box"}, {BuiltinMesh::Sphere, "sphere"}}};

Model makeBuiltinModel() {
    Model model;
    model.sourcePath = "builtin";
    Material grey;
    grey.name = "builtin grey";
    grey.baseColorFactor = {0.6f, 0.6f, 0.6f, 1.0f};
    grey.metallicFactor = 0.0f;
    grey.roughnessFactor = 0.6f;
    model.materials.push_back(grey);
    for (Primitive primitive :
         {makePlane(0.5f), makeBox({0.5f, 0.5f, 0.5f}), makeSphere(0.5f, 48, 24)}) {
        primitive.material = 0;
        Mesh mesh;
        mesh.primitives.push_back(std::move(primitive));
        model.meshes.push_back(std::move(mesh));
    }
    return model;
}

}  // namespace

std::string_view builtinMeshName(BuiltinMesh mesh) {
    for (const auto& [value, name] : kNames) {
        if (value == mesh) return name;
    }
    return kNames[0].second;
}

std::optional<BuiltinMesh> builtinMeshFromName(std::string_view name) {
    for (const auto& [value, spelled] : kNames) {
        if (spelled == name) return value;
    }
    return std::nullopt;
}

std::string_view builtinMeshNames() {
    return "plane, box, sphere";
}

const Model& builtinMeshModel() {
    static const Model model = makeBuiltinModel();
    return model;
}

}  // namespace candela::content
