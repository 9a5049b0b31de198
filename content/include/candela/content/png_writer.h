#pragma once
// 8-bit PNG writing (frame captures, golden diff images).
#include <cstdint>
#include <filesystem>
#include <string>

namespace candela::content {

// `pixels`: width * height * channels bytes (1..4 channels), row-major, top row first.
// Returns an empty string on success, else a message naming the file and the problem.
std::string writePng(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
                     int channels, const std::uint8_t* pixels);

}  // namespace candela::content
