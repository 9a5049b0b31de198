#pragma once
// CPU-side asset cache: each glTF, mesh, texture (with its mips, per colour space), EXR
// environment and audio clip is loaded or built once, however many entities refer to it, keyed by
// canonical file path plus index. The renderer uploads what it gets from here and keys its GPU
// copies by the same pointer, so an asset used twice is also uploaded once.
//
//   AssetCache cache;
//   Diagnostics diagnostics;
//   auto mesh = cache.mesh("models/Box.glb", 0, diagnostics);           // loads Box.glb
//   auto again = cache.mesh("models/../models/Box.glb", 0, diagnostics); // same pointer
//   auto albedo = cache.texture("models/Box.glb", 0, ColorSpace::Srgb, diagnostics);
//
// Failed loads are remembered too (as null), so a missing file is reported once, not every
// time something asks for it. Thread-safe.
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <tuple>
#include <vector>

#include "candela/content/audio_clip.h"
#include "candela/content/diagnostics.h"
#include "candela/content/environment_map.h"
#include "candela/content/gltf_loader.h"
#include "candela/content/model.h"

namespace candela::content {

struct PreparedTexture {
    std::vector<Rgba8Image> mips;  // level 0 first, down to 1x1
    ColorSpace colorSpace = ColorSpace::Linear;
    Sampler sampler;
    bool isFallback = false;  // the magenta checker stands in for a missing image
};

class AssetCache {
public:
    struct Stats {
        std::uint64_t modelLoads = 0;        // glTF files read from disk
        std::uint64_t textureBuilds = 0;     // mip chains built
        std::uint64_t environmentLoads = 0;  // EXR files read
        std::uint64_t audioClipLoads = 0;    // WAV and Ogg Vorbis files read
        std::uint64_t hits = 0;              // requests answered from the cache
    };

    explicit AssetCache(GltfLoadOptions options = {}) : options_(options) {}

    std::shared_ptr<const Model> model(const std::filesystem::path& path, Diagnostics& diagnostics);
    // Null when the file failed or the index is out of range (with a message).
    std::shared_ptr<const Mesh> mesh(const std::filesystem::path& path, std::int32_t meshIndex,
                                     Diagnostics& diagnostics);
    std::shared_ptr<const PreparedTexture> texture(const std::filesystem::path& path,
                                                   std::int32_t textureIndex, ColorSpace colorSpace,
                                                   Diagnostics& diagnostics);
    std::shared_ptr<const EnvironmentMap> environment(const std::filesystem::path& path,
                                                      Diagnostics& diagnostics);
    // A WAV or Ogg Vorbis clip (audio_clip.h); null (silence) when the file is bad.
    std::shared_ptr<const AudioClip> audioClip(const std::filesystem::path& path,
                                               Diagnostics& diagnostics);

    Stats stats() const;
    void clear();

    // The key every lookup uses: absolute, with "." and ".." resolved and links followed
    // where the file exists.
    static std::filesystem::path canonicalKey(const std::filesystem::path& path);

private:
    std::shared_ptr<const Model> modelLocked(const std::filesystem::path& key,
                                             Diagnostics& diagnostics);

    GltfLoadOptions options_;
    mutable std::mutex mutex_;
    std::map<std::filesystem::path, std::shared_ptr<const Model>> models_;
    std::map<std::tuple<std::filesystem::path, std::int32_t, ColorSpace>,
             std::shared_ptr<const PreparedTexture>>
        textures_;
    std::map<std::filesystem::path, std::shared_ptr<const EnvironmentMap>> environments_;
    std::map<std::filesystem::path, std::shared_ptr<const AudioClip>> audioClips_;
    Stats stats_;
};

}  // namespace candela::content
