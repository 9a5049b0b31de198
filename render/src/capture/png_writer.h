#pragma once
#include <cstdint>
#include <filesystem>
#include <string>

namespace candela::render {

// 8-bit RGBA PNG. Returns an empty string on success, else a message naming the file.
std::string writePngRgba(const std::filesystem::path& path, uint32_t width, uint32_t height,
                         const uint8_t* rgba);

}  // namespace candela::render
