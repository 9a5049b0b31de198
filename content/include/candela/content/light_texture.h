#pragma once
// The emissive images of textured rect lights (issue 15). glTF extras.texture and scene files'
// "texture" name a PNG or JPEG file relative to the file that names it; Light::texture holds an
// id into a process-wide table of (file, image), so Light stays trivially copyable. Ids start
// at 1 and are never reused; entries live as long as the process (a scene has a handful).
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "candela/content/image.h"

namespace candela::content {

struct LightTexture {
    std::string file;                         // as the scene file or glTF wrote it
    std::shared_ptr<const Rgba8Image> image;  // null: not loaded (yet), or unreadable
};

// Adds an entry; returns its id (>= 1). Thread-safe.
std::uint32_t registerLightTexture(std::string file, std::shared_ptr<const Rgba8Image> image);
// The entry of `id`; null for 0 or an id never registered. Thread-safe.
std::shared_ptr<const LightTexture> findLightTexture(std::uint32_t id);

// Decodes `file` for a light texture. On failure returns null and sets `error` to the problem
// (without the path: the caller names the file and the light); the light then stays an
// untextured rect.
std::shared_ptr<const Rgba8Image> loadLightTexture(const std::filesystem::path& file,
                                                   std::string& error);

}  // namespace candela::content
