#pragma once
// Checks the GLB container (header and chunk table) before tinygltf parses it: tinygltf's own
// checks miss the 8-byte chunk header when bounding the BIN chunk.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

namespace candela::content::gltf {

bool looksLikeGlb(std::span<const std::byte> bytes);

// Returns an empty string when the header, JSON chunk and optional BIN chunk all lie inside
// `bytes` and agree with the declared length; `declaredLength` receives that length.
std::string checkGlbContainer(std::span<const std::byte> bytes, std::uint64_t& declaredLength);

// Length of the JSON chunk (which starts at byte 20); only valid after checkGlbContainer().
std::uint64_t glbJsonLength(std::span<const std::byte> bytes);

}  // namespace candela::content::gltf
