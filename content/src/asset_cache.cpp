#include "candela/content/asset_cache.h"

#include "candela/content/mip_generation.h"

namespace candela::content {

namespace {

// The file loaded once per key: a cached result (a failed load caches null, so it is not
// retried) counts as a hit; otherwise `load` (an optional value) runs and counts in `loads`.
template <typename Value, typename Load>
std::shared_ptr<const Value> cachedLoad(
    std::map<std::filesystem::path, std::shared_ptr<const Value>>& cache,
    const std::filesystem::path& key, std::uint64_t& hits, std::uint64_t& loads, Load load) {
    if (auto it = cache.find(key); it != cache.end()) {
        ++hits;
        return it->second;
    }
    ++loads;
    std::shared_ptr<const Value> loaded;
    if (auto value = load()) loaded = std::make_shared<const Value>(std::move(*value));
    cache.emplace(key, loaded);
    return loaded;
}

}  // namespace

std::filesystem::path AssetCache::canonicalKey(const std::filesystem::path& path) {
    std::error_code ec;
    std::filesystem::path key = std::filesystem::weakly_canonical(path, ec);
    return ec ? std::filesystem::absolute(path).lexically_normal() : key;
}

std::shared_ptr<const Model> AssetCache::modelLocked(const std::filesystem::path& key,
                                                     Diagnostics& diagnostics) {
    return cachedLoad(models_, key, stats_.hits, stats_.modelLoads,
                      [&] { return loadGltf(key, diagnostics, options_); });
}

std::shared_ptr<const Model> AssetCache::model(const std::filesystem::path& path,
                                               Diagnostics& diagnostics) {
    const std::filesystem::path key = canonicalKey(path);
    std::lock_guard lock(mutex_);
    return modelLocked(key, diagnostics);
}

std::shared_ptr<const Mesh> AssetCache::mesh(const std::filesystem::path& path,
                                             std::int32_t meshIndex, Diagnostics& diagnostics) {
    const std::filesystem::path key = canonicalKey(path);
    std::lock_guard lock(mutex_);
    std::shared_ptr<const Model> owner = modelLocked(key, diagnostics);
    if (!owner) return nullptr;
    if (meshIndex < 0 || static_cast<std::size_t>(meshIndex) >= owner->meshes.size()) {
        diagnostics.error(
            key.string(), "meshes[" + std::to_string(meshIndex) + "]",
            "no such mesh (the file has " + std::to_string(owner->meshes.size()) + ")");
        return nullptr;
    }
    // Aliasing pointer: the mesh lives inside the cached model; no copy.
    return {owner, &owner->meshes[static_cast<std::size_t>(meshIndex)]};
}

std::shared_ptr<const PreparedTexture> AssetCache::texture(const std::filesystem::path& path,
                                                           std::int32_t textureIndex,
                                                           ColorSpace colorSpace,
                                                           Diagnostics& diagnostics) {
    const std::filesystem::path key = canonicalKey(path);
    std::lock_guard lock(mutex_);
    const auto textureKey = std::make_tuple(key, textureIndex, colorSpace);
    if (auto it = textures_.find(textureKey); it != textures_.end()) {
        ++stats_.hits;
        return it->second;
    }
    std::shared_ptr<const Model> owner = modelLocked(key, diagnostics);
    std::shared_ptr<const PreparedTexture> prepared;
    if (owner && textureIndex >= 0 &&
        static_cast<std::size_t>(textureIndex) < owner->textures.size()) {
        const Texture& source = owner->textures[static_cast<std::size_t>(textureIndex)];
        const Rgba8Image& image = owner->images[static_cast<std::size_t>(source.image)];
        auto built = std::make_shared<PreparedTexture>();
        built->mips = generateMipChain(image, colorSpace);
        built->colorSpace = colorSpace;
        built->sampler = source.sampler;
        built->isFallback = image.isFallback;
        ++stats_.textureBuilds;
        prepared = std::move(built);
    } else if (owner) {
        diagnostics.error(key.string(), "textures[" + std::to_string(textureIndex) + "]",
                          "no such texture");
    }
    textures_.emplace(textureKey, prepared);
    return prepared;
}

std::shared_ptr<const EnvironmentMap> AssetCache::environment(const std::filesystem::path& path,
                                                              Diagnostics& diagnostics) {
    const std::filesystem::path key = canonicalKey(path);
    std::lock_guard lock(mutex_);
    return cachedLoad(environments_, key, stats_.hits, stats_.environmentLoads,
                      [&] { return loadEnvironmentExr(key, diagnostics); });
}

std::shared_ptr<const AudioClip> AssetCache::audioClip(const std::filesystem::path& path,
                                                       Diagnostics& diagnostics) {
    const std::filesystem::path key = canonicalKey(path);
    std::lock_guard lock(mutex_);
    return cachedLoad(audioClips_, key, stats_.hits, stats_.audioClipLoads,
                      [&] { return loadAudioClip(key, diagnostics); });
}

AssetCache::Stats AssetCache::stats() const {
    std::lock_guard lock(mutex_);
    return stats_;
}

void AssetCache::clear() {
    std::lock_guard lock(mutex_);
    models_.clear();
    textures_.clear();
    environments_.clear();
    audioClips_.clear();
}

}  // namespace candela::content
