// libFuzzer target: any bytes through the glTF loader (GLB or JSON). External files are
// refused so the fuzzer cannot wander the filesystem; limits are lowered to keep runs fast.
#include <cstddef>
#include <cstdint>

#include "candela/content/gltf_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    candela::content::GltfLoadOptions options;
    options.allowExternalFiles = false;
    options.maxImageDimension = 1024;
    options.maxVerticesPerPrimitive = 1u << 18;
    options.maxIndicesPerPrimitive = 1u << 20;
    options.maxElementsWithoutBufferView = 1u << 16;
    candela::content::Diagnostics diagnostics;
    auto model = candela::content::loadGltfFromMemory(
        {reinterpret_cast<const std::byte*>(data), size}, "fuzz.gltf", diagnostics, options);
    if (model) {
        // What the loader promises: every index addresses a vertex, every reference is valid.
        for (const auto& mesh : model->meshes) {
            for (const auto& primitive : mesh.primitives) {
                for (std::uint32_t index : primitive.indices) {
                    if (index >= primitive.positions.size()) __builtin_trap();
                }
                if (primitive.normals.size() != primitive.positions.size()) __builtin_trap();
            }
        }
        for (const auto& texture : model->textures) {
            if (texture.image < 0 ||
                static_cast<std::size_t>(texture.image) >= model->images.size()) {
                __builtin_trap();
            }
        }
    }
    return 0;
}
