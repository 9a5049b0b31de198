#include "lit_scene_gltf.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>
#include <vector>

#include "candela/content/procedural_mesh.h"

namespace candela::golden::test {

namespace {

using content::Primitive;
using nlohmann::json;

std::string base64(const std::vector<std::uint8_t>& bytes) {
    static const char* kAlphabet =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        std::uint32_t chunk = std::uint32_t(bytes[i]) << 16;
        if (i + 1 < bytes.size()) chunk |= std::uint32_t(bytes[i + 1]) << 8;
        if (i + 2 < bytes.size()) chunk |= bytes[i + 2];
        out += kAlphabet[(chunk >> 18) & 63];
        out += kAlphabet[(chunk >> 12) & 63];
        out += i + 1 < bytes.size() ? kAlphabet[(chunk >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? kAlphabet[chunk & 63] : '=';
    }
    return out;
}

// Appends primitives to one buffer, one buffer view and accessor per stream.
class BufferBuilder {
public:
    explicit BufferBuilder(json& document) : document_(document) {}

    json addPrimitive(const Primitive& primitive, int material) {
        json attributes;
        attributes["POSITION"] = addFloats(primitive.positions, 34962, true);
        attributes["NORMAL"] = addFloats(primitive.normals, 34962, false);
        const int indices = addIndices(primitive.indices);
        return json{{"attributes", attributes}, {"indices", indices}, {"material", material}};
    }

    void finish() {
        document_["buffers"] =
            json::array({{{"byteLength", bytes_.size()},
                          {"uri", "data:application/octet-stream;base64," + base64(bytes_)}}});
    }

private:
    int addView(const void* data, std::size_t size, int target) {
        while (bytes_.size() % 4 != 0)
            bytes_.push_back(0);
        const std::size_t offset = bytes_.size();
        bytes_.resize(offset + size);
        std::memcpy(bytes_.data() + offset, data, size);
        document_["bufferViews"].push_back(
            {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", size}, {"target", target}});
        return int(document_["bufferViews"].size()) - 1;
    }

    int addFloats(const std::vector<content::Float3>& values, int target, bool withBounds) {
        json accessor = {{"bufferView", addView(values.data(), values.size() * 12, target)},
                         {"componentType", 5126},
                         {"count", values.size()},
                         {"type", "VEC3"}};
        if (withBounds) {  // glTF requires min/max on POSITION
            content::Float3 lo = values[0], hi = values[0];
            for (const content::Float3& v : values) {
                for (int c = 0; c < 3; ++c) {
                    lo[c] = std::min(lo[c], v[c]);
                    hi[c] = std::max(hi[c], v[c]);
                }
            }
            accessor["min"] = lo;
            accessor["max"] = hi;
        }
        document_["accessors"].push_back(accessor);
        return int(document_["accessors"].size()) - 1;
    }

    int addIndices(const std::vector<std::uint32_t>& indices) {
        document_["accessors"].push_back(
            {{"bufferView", addView(indices.data(), indices.size() * 4, 34963)},
             {"componentType", 5125},
             {"count", indices.size()},
             {"type", "SCALAR"}});
        return int(document_["accessors"].size()) - 1;
    }

    json& document_;
    std::vector<std::uint8_t> bytes_;
};

json sphereMaterial(const LitScene& scene) {
    json material = {
        {"name", "sphere"},
        {"pbrMetallicRoughness",
         {{"baseColorFactor",
           {scene.sphereBaseColor[0], scene.sphereBaseColor[1], scene.sphereBaseColor[2], 1.0f}},
          {"metallicFactor", scene.sphereMetallic},
          {"roughnessFactor", scene.sphereRoughness}}},
        {"extras",
         {{"shadingModel", scene.sphereShadingModel},
          {"diffuseColor", scene.sphereBaseColor},
          {"specularColor", {0.04f, 0.04f, 0.04f}}}}};
    return material;
}

}  // namespace

std::string litSceneGltf(const LitScene& scene) {
    json document = {{"asset", {{"version", "2.0"}, {"generator", "candela golden self tests"}}},
                     {"extensionsUsed", {"KHR_lights_punctual"}},
                     {"scene", 0},
                     {"bufferViews", json::array()},
                     {"accessors", json::array()}};
    document["materials"] = {sphereMaterial(scene),
                             {{"name", "floor"},
                              {"pbrMetallicRoughness",
                               {{"baseColorFactor", {0.5f, 0.5f, 0.5f, 1.0f}},
                                {"metallicFactor", 0.0f},
                                {"roughnessFactor", 0.8f}}}}};

    BufferBuilder buffer(document);
    document["meshes"] = {
        {{"name", "sphere"},
         {"primitives", {buffer.addPrimitive(content::makeSphere(0.5f, 48, 24), 0)}}},
        {{"name", "floor"}, {"primitives", {buffer.addPrimitive(content::makePlane(1.5f), 1)}}}};
    buffer.finish();

    document["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "point"},
                                                                {"color", {1.0f, 1.0f, 1.0f}},
                                                                {"intensity", scene.lightCandela},
                                                                {"range", scene.lightRange}}};
    document["cameras"] = {
        {{"type", "perspective"}, {"perspective", {{"yfov", 0.7f}, {"znear", 0.05f}}}}};

    // The camera at (0, 1, 2.6) pitched down to look at the sphere's centre (0, 0.5, 0).
    const double pitch = -std::atan2(0.5, 2.6);
    document["nodes"] = {{{"name", "sphere"}, {"mesh", 0}, {"translation", {0.0f, 0.5f, 0.0f}}},
                         {{"name", "floor"}, {"mesh", 1}},
                         {{"name", "light"},
                          {"translation", scene.lightPosition},
                          {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}},
                         {{"name", "camera"},
                          {"camera", 0},
                          {"translation", {0.0f, 1.0f, 2.6f}},
                          {"rotation", {std::sin(pitch / 2), 0.0, 0.0, std::cos(pitch / 2)}}}};
    document["scenes"] = {{{"nodes", {0, 1, 2, 3}}}};
    return document.dump(1);
}

}  // namespace candela::golden::test
