#include "glb_container.h"

#include <cstring>

namespace candela::content::gltf {
namespace {

constexpr std::uint32_t kMagic = 0x46546C67;      // "glTF"
constexpr std::uint32_t kJsonChunk = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kBinChunk = 0x004E4942;   // "BIN\0"

std::uint32_t readU32(std::span<const std::byte> bytes, std::uint64_t offset) {
    std::uint32_t v;
    std::memcpy(&v, bytes.data() + offset, 4);  // GLB is little-endian, as are our targets
    return v;
}

}  // namespace

std::uint64_t glbJsonLength(std::span<const std::byte> bytes) {
    return readU32(bytes, 12);
}

bool looksLikeGlb(std::span<const std::byte> bytes) {
    return bytes.size() >= 4 && readU32(bytes, 0) == kMagic;
}

std::string checkGlbContainer(std::span<const std::byte> bytes, std::uint64_t& declaredLength) {
    if (bytes.size() < 20) return "GLB is truncated (" + std::to_string(bytes.size()) + " bytes)";
    if (readU32(bytes, 0) != kMagic) return "not a GLB file (bad magic)";
    if (const std::uint32_t version = readU32(bytes, 4); version != 2) {
        return "GLB version " + std::to_string(version) + " is not supported (need 2)";
    }
    declaredLength = readU32(bytes, 8);
    if (declaredLength > bytes.size()) {
        return "GLB header declares " + std::to_string(declaredLength) +
               " bytes but the file has " + std::to_string(bytes.size()) + " (truncated?)";
    }
    const std::uint64_t jsonLength = readU32(bytes, 12);
    if (readU32(bytes, 16) != kJsonChunk) return "first GLB chunk is not JSON";
    if (jsonLength == 0 || 20 + jsonLength > declaredLength) {
        return "GLB JSON chunk of " + std::to_string(jsonLength) + " bytes overruns the file";
    }
    // The spec pads chunks to 4 bytes; tinygltf looks for BIN right after the declared length.
    if (jsonLength % 4 != 0) return "GLB JSON chunk length is not a multiple of 4";
    const std::uint64_t offset = 20 + jsonLength;
    if (offset + 8 <= declaredLength) {
        const std::uint64_t binLength = readU32(bytes, offset);
        const std::uint32_t type = readU32(bytes, offset + 4);
        if (type == kBinChunk && offset + 8 + binLength > declaredLength) {
            return "GLB BIN chunk of " + std::to_string(binLength) + " bytes overruns the file";
        }
    }
    return {};
}

}  // namespace candela::content::gltf
