#pragma once
// glTF 2.0 loading (.gltf with external or data-URI buffers, and .glb) into a plain Model.
//
//   candela::content::Diagnostics diagnostics;
//   std::optional<Model> model = loadGltf("DamagedHelmet.glb", diagnostics);
//   for (const Diagnostic& d : diagnostics.messages) log(formatDiagnostic(d));
//
// nullopt means nothing usable could be read (not glTF, truncated, unsupported required
// extension). Otherwise the model holds everything that loaded; each skipped primitive, node
// transform or image has a message naming file, element and problem.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>

#include "candela/content/diagnostics.h"
#include "candela/content/model.h"

namespace candela::content {

struct GltfLoadOptions {
    bool allowExternalFiles = true;  // false: only data URIs and the GLB BIN chunk (fuzzing)
    std::uint64_t maxFileBytes = 2ull * 1024 * 1024 * 1024;
    std::uint32_t maxImageDimension = 16384;
    std::uint64_t maxVerticesPerPrimitive = 1u << 24;
    std::uint64_t maxIndicesPerPrimitive = 1u << 26;
    std::uint64_t maxElementsWithoutBufferView = 1u << 20;
    bool generateTangents = true;  // MikkTSpace-equivalent, where the file has none
};

std::optional<Model> loadGltf(const std::filesystem::path& path, Diagnostics& diagnostics,
                              const GltfLoadOptions& options = {});

// `path` names the data in messages and is the base for relative URIs.
std::optional<Model> loadGltfFromMemory(std::span<const std::byte> bytes,
                                        const std::filesystem::path& path, Diagnostics& diagnostics,
                                        const GltfLoadOptions& options = {});

}  // namespace candela::content
