#include "ibl/environment_cache.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "candela/content/atomic_file_write.h"

namespace candela::render {

namespace {

constexpr char kMagic[8] = {'C', 'A', 'N', 'D', 'I', 'B', 'L', '1'};

struct Header {
    char magic[8];
    uint32_t version;
    uint32_t cubeFaceSize;
    uint32_t cubeMipCount;
    uint32_t prefilteredFaceSize;
    uint32_t prefilteredMipCount;
    uint32_t reserved;
    uint64_t cubeBytes;
    uint64_t prefilteredBytes;
    uint64_t shBytes;
    uint64_t payloadChecksum;
};

constexpr uint64_t kFnvPrime = 1099511628211ull;

uint64_t payloadChecksum(const CachedEnvironment& e) {
    uint64_t h = fnv1a64(e.cube.data(), e.cube.size());
    h = fnv1a64(e.prefiltered.data(), e.prefiltered.size(), h);
    return fnv1a64(e.irradianceSh.data(), e.irradianceSh.size(), h);
}

// RGBA16F texels: a half is NaN or Inf when its five exponent bits are all set.
bool halvesFinite(const std::vector<uint8_t>& bytes) {
    for (size_t i = 0; i + 1 < bytes.size(); i += 2) {
        uint16_t half;
        std::memcpy(&half, bytes.data() + i, sizeof(half));
        if ((half & 0x7C00u) == 0x7C00u) return false;
    }
    return true;
}

bool floatsFinite(const std::vector<uint8_t>& bytes) {
    for (size_t i = 0; i + sizeof(float) <= bytes.size(); i += sizeof(float)) {
        float value;
        std::memcpy(&value, bytes.data() + i, sizeof(value));
        if (!std::isfinite(value)) return false;
    }
    return true;
}

}  // namespace

uint64_t fnv1a64(const void* data, size_t bytes, uint64_t hash) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < bytes; ++i)
        hash = (hash ^ p[i]) * kFnvPrime;
    return hash;
}

uint64_t contentHash(std::span<const std::byte> bytes) {
    const uint64_t h = fnv1a64(bytes.data(), bytes.size());
    return fnv1a64(&kEnvironmentPrecomputeVersion, sizeof(kEnvironmentPrecomputeVersion), h);
}

std::filesystem::path environmentCachePath(const std::filesystem::path& directory, uint64_t hash) {
    char name[40];
    std::snprintf(name, sizeof(name), "env-%016llx.cibl", static_cast<unsigned long long>(hash));
    return directory / name;
}

std::optional<CachedEnvironment> readCachedEnvironment(const std::filesystem::path& path,
                                                       std::string& problem) {
    // Only a regular file is opened (a FIFO planted in the cache would block the open).
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        if (std::filesystem::exists(path, ec)) problem = "not a regular file";
        return std::nullopt;
    }
    const std::uintmax_t fileBytes = std::filesystem::file_size(path, ec);
    std::ifstream in(path, std::ios::binary);
    if (ec || !in) return std::nullopt;
    Header h{};
    if (!in.read(reinterpret_cast<char*>(&h), sizeof(h)) ||
        std::memcmp(h.magic, kMagic, sizeof(kMagic)) != 0 ||
        h.version != kEnvironmentPrecomputeVersion) {
        problem = "not a cache entry of this version";
        return std::nullopt;
    }
    EnvironmentSizes expected = environmentSizesFor(h.cubeFaceSize);
    if (expected.cubeFaceSize != h.cubeFaceSize || expected.cubeMipCount != h.cubeMipCount ||
        expected.prefilteredFaceSize != h.prefilteredFaceSize ||
        expected.prefilteredMipCount != h.prefilteredMipCount || h.shBytes != 9 * 16 ||
        h.cubeBytes == 0 || h.prefilteredBytes == 0 || h.cubeBytes > (uint64_t(1) << 32) ||
        h.prefilteredBytes > (uint64_t(1) << 32)) {
        problem = "header sizes are inconsistent";
        return std::nullopt;
    }
    // Nothing is allocated for sizes the file cannot hold (a corrupt header).
    if (fileBytes != sizeof(Header) + h.cubeBytes + h.prefilteredBytes + h.shBytes) {
        problem = "truncated";
        return std::nullopt;
    }
    CachedEnvironment e;
    e.sizes = expected;
    e.cube.resize(h.cubeBytes);
    e.prefiltered.resize(h.prefilteredBytes);
    e.irradianceSh.resize(h.shBytes);
    if (!in.read(reinterpret_cast<char*>(e.cube.data()), std::streamsize(e.cube.size())) ||
        !in.read(reinterpret_cast<char*>(e.prefiltered.data()),
                 std::streamsize(e.prefiltered.size())) ||
        !in.read(reinterpret_cast<char*>(e.irradianceSh.data()),
                 std::streamsize(e.irradianceSh.size()))) {
        problem = "truncated";
        return std::nullopt;
    }
    if (payloadChecksum(e) != h.payloadChecksum) {
        problem = "checksum mismatch";
        return std::nullopt;
    }
    // A checksum proves only that the bytes are the ones written: a payload that is not finite
    // (from a build with a bug, or forged) would light every later run with NaN.
    if (!halvesFinite(e.cube) || !halvesFinite(e.prefiltered) || !floatsFinite(e.irradianceSh)) {
        problem = "its payload holds NaN or Inf";
        return std::nullopt;
    }
    return e;
}

std::string writeCachedEnvironment(const std::filesystem::path& path, const CachedEnvironment& e) {
    std::error_code ec;
    std::filesystem::create_directories(path.parent_path(), ec);
    if (ec) return "cannot create " + path.parent_path().string() + ": " + ec.message();
    Header h{};
    std::memcpy(h.magic, kMagic, sizeof(kMagic));
    h.version = kEnvironmentPrecomputeVersion;
    h.cubeFaceSize = e.sizes.cubeFaceSize;
    h.cubeMipCount = e.sizes.cubeMipCount;
    h.prefilteredFaceSize = e.sizes.prefilteredFaceSize;
    h.prefilteredMipCount = e.sizes.prefilteredMipCount;
    h.cubeBytes = e.cube.size();
    h.prefilteredBytes = e.prefiltered.size();
    h.shBytes = e.irradianceSh.size();
    h.payloadChecksum = payloadChecksum(e);
    std::string bytes;
    bytes.reserve(sizeof(h) + e.cube.size() + e.prefiltered.size() + e.irradianceSh.size());
    bytes.append(reinterpret_cast<const char*>(&h), sizeof(h));
    bytes.append(reinterpret_cast<const char*>(e.cube.data()), e.cube.size());
    bytes.append(reinterpret_cast<const char*>(e.prefiltered.data()), e.prefiltered.size());
    bytes.append(reinterpret_cast<const char*>(e.irradianceSh.data()), e.irradianceSh.size());
    // Atomic (unique temporary, fsync, rename), so two runs filling the cache at once, or a
    // full disk, never leave a half-written entry behind.
    return content::writeFileAtomically(path, bytes);
}

}  // namespace candela::render
