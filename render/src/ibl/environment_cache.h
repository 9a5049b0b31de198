#pragma once
// The on-disk cache of precomputed environments, keyed by the source file's content hash
// (FNV-1a 64 of its bytes, combined with the precompute version). One file per environment:
//   header (magic, version, sizes, payload checksum) | cube mips | prefiltered mips | SH
// A file that does not match its header or checksum, or whose payload is not finite, is ignored
// and rewritten; writes go to a temporary file that is renamed into place, so a crash never
// leaves a partial entry.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "ibl/environment_precompute.h"

namespace candela::render {

// Bump when the precompute's output changes for the same input (shaders, sizes, sampling).
constexpr uint32_t kEnvironmentPrecomputeVersion = 1;

uint64_t contentHash(std::span<const std::byte> bytes);
// FNV-1a 64 continued from `hash` (the cache files' key and payload checksum).
constexpr uint64_t kFnv1aOffset = 1469598103934665603ull;
uint64_t fnv1a64(const void* data, size_t bytes, uint64_t hash = kFnv1aOffset);

struct CachedEnvironment {
    EnvironmentSizes sizes{};
    std::vector<uint8_t> cube;          // RGBA16F, mip-major, six faces per mip
    std::vector<uint8_t> prefiltered;   // same layout
    std::vector<uint8_t> irradianceSh;  // 9 x vec4 float
};

std::filesystem::path environmentCachePath(const std::filesystem::path& directory, uint64_t hash);

// Nullopt when absent, unreadable or inconsistent (then `problem` says why, if it existed).
std::optional<CachedEnvironment> readCachedEnvironment(const std::filesystem::path& path,
                                                       std::string& problem);
// Empty string on success, else what went wrong.
std::string writeCachedEnvironment(const std::filesystem::path& path,
                                   const CachedEnvironment& entry);

}  // namespace candela::render
