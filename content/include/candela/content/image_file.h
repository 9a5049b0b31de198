#pragma once
// A PNG or JPEG file decoded to 8-bit RGBA (interface images, icons), with the same limits and
// checks as glTF textures. Null on failure, with an error naming the file.
#include <filesystem>
#include <optional>

#include "candela/content/diagnostics.h"
#include "candela/content/image.h"

namespace candela::content {

inline constexpr std::uint64_t kMaxImageFileBytes = 256ull * 1024 * 1024;

std::optional<Rgba8Image> loadImageFile(const std::filesystem::path& path,
                                        Diagnostics& diagnostics);

}  // namespace candela::content
