#include "candela/content/light_texture.h"

#include <cstdint>
#include <mutex>
#include <span>
#include <vector>

#include "candela/content/file_bytes.h"
#include "image_decoding.h"

namespace candela::content {

namespace {

struct LightTextureTable {
    std::mutex mutex;
    std::vector<std::shared_ptr<const LightTexture>> entries;  // id - 1
};

LightTextureTable& table() {
    static LightTextureTable instance;
    return instance;
}

}  // namespace

std::uint32_t registerLightTexture(std::string file, std::shared_ptr<const Rgba8Image> image) {
    auto entry = std::make_shared<LightTexture>(LightTexture{std::move(file), std::move(image)});
    LightTextureTable& t = table();
    std::lock_guard lock(t.mutex);
    t.entries.push_back(std::move(entry));
    return std::uint32_t(t.entries.size());
}

std::shared_ptr<const LightTexture> findLightTexture(std::uint32_t id) {
    LightTextureTable& t = table();
    std::lock_guard lock(t.mutex);
    return id >= 1 && id <= t.entries.size() ? t.entries[id - 1] : nullptr;
}

std::shared_ptr<const Rgba8Image> loadLightTexture(const std::filesystem::path& file,
                                                   std::string& error) {
    // A light's image is shown filtered down to at most a few hundred texels a side
    // (render/src/lights/area_light_textures.h); 64 MiB holds any sensible PNG or JPEG.
    constexpr std::uint64_t kMaxBytes = 64ull << 20;
    const FileBytes read = readFileBytes(file, kMaxBytes);
    if (!read.error.empty()) {
        error = read.error;
        return nullptr;
    }
    auto image = std::make_shared<Rgba8Image>();
    const std::span<const std::uint8_t> bytes(
        reinterpret_cast<const std::uint8_t*>(read.bytes.data()), read.bytes.size());
    error = decodeImageRgba8(bytes, *image);
    if (!error.empty()) return nullptr;
    if (image->width == 0 || image->height == 0) {
        error = "the image is empty";
        return nullptr;
    }
    return image;
}

}  // namespace candela::content
