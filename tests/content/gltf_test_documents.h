#pragma once
// Builds small glTF documents in memory for tests: a binary buffer assembled from typed
// arrays, base64 data URIs, and JSON edited with nlohmann::json to break things on purpose.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <vector>

namespace candela::content::testing {

inline std::string base64(std::span<const std::uint8_t> bytes) {
    static const char* alphabet =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const std::uint32_t v = (bytes[i] << 16) | (bytes[i + 1] << 8) | bytes[i + 2];
        for (int s = 18; s >= 0; s -= 6)
            out += alphabet[(v >> s) & 63];
    }
    if (i + 1 == bytes.size()) {
        const std::uint32_t v = bytes[i] << 16;
        out += alphabet[(v >> 18) & 63];
        out += alphabet[(v >> 12) & 63];
        out += "==";
    } else if (i + 2 == bytes.size()) {
        const std::uint32_t v = (bytes[i] << 16) | (bytes[i + 1] << 8);
        out += alphabet[(v >> 18) & 63];
        out += alphabet[(v >> 12) & 63];
        out += alphabet[(v >> 6) & 63];
        out += '=';
    }
    return out;
}

// A growing binary buffer; append() returns the byte offset where the data starts (4-aligned).
struct BinaryBuffer {
    std::vector<std::uint8_t> bytes;

    template <typename T>
    std::size_t append(const std::vector<T>& values) {
        while (bytes.size() % 4 != 0)
            bytes.push_back(0);
        const std::size_t offset = bytes.size();
        bytes.resize(offset + values.size() * sizeof(T));
        std::memcpy(bytes.data() + offset, values.data(), values.size() * sizeof(T));
        return offset;
    }
    std::string dataUri() const { return "data:application/octet-stream;base64," + base64(bytes); }
};

// One quad (two triangles) in the XY plane facing +Z with UVs, u16 indices, and a material,
// as a complete glTF JSON with a data-URI buffer. Tests edit the returned JSON to break it.
inline nlohmann::json quadDocument() {
    BinaryBuffer buffer;
    const std::vector<float> positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    const std::vector<float> uvs = {0, 1, 1, 1, 1, 0, 0, 0};  // v down the image, as glTF
    const std::vector<std::uint16_t> indices = {0, 1, 2, 0, 2, 3};
    const std::size_t p = buffer.append(positions);
    const std::size_t t = buffer.append(uvs);
    const std::size_t i = buffer.append(indices);
    using nlohmann::json;
    json doc = {
        {"asset", {{"version", "2.0"}}},
        {"scene", 0},
        {"scenes", json::array({{{"nodes", {0}}}})},
        {"nodes", json::array({{{"name", "quad"}, {"mesh", 0}}})},
        {"meshes",
         json::array(
             {{{"name", "quadMesh"},
               {"primitives", json::array({{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}},
                                            {"indices", 2},
                                            {"material", 0}}})}}})},
        {"materials", json::array({{{"name", "plain"}}})},
        {"accessors",
         json::array(
             {{{"bufferView", 0},
               {"componentType", 5126},
               {"count", 4},
               {"type", "VEC3"},
               {"min", {0, 0, 0}},
               {"max", {1, 1, 0}}},
              {{"bufferView", 1}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}},
              {{"bufferView", 2}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}})},
        {"bufferViews", json::array({{{"buffer", 0}, {"byteOffset", p}, {"byteLength", 48}},
                                     {{"buffer", 0}, {"byteOffset", t}, {"byteLength", 32}},
                                     {{"buffer", 0}, {"byteOffset", i}, {"byteLength", 12}}})},
        {"buffers",
         json::array({{{"byteLength", buffer.bytes.size()}, {"uri", buffer.dataUri()}}})},
    };
    return doc;
}

inline std::vector<std::byte> bytesOf(const std::string& text) {
    std::vector<std::byte> out(text.size());
    if (!text.empty()) std::memcpy(out.data(), text.data(), text.size());
    return out;
}

}  // namespace candela::content::testing
