#pragma once
// Reading and writing the files a golden test works with. Errors come back as text naming
// the file; nothing throws.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "golden_image.h"

namespace candela::golden {

struct LoadedHdr {
    HdrImage image;
    // Texels that held NaN or Inf in the file (the reader makes them finite, so the count is
    // the only trace of them; a golden fails on any).
    std::uint64_t nonFiniteTexels = 0;
};

std::optional<LoadedHdr> readHdrExr(const std::filesystem::path& path, std::string& error);
std::optional<LdrImage> readLdrPng(const std::filesystem::path& path, std::string& error);

// Return an empty string on success, else what went wrong.
std::string writeHdrExr(const std::filesystem::path& path, const HdrImage& image);
std::string writeLdrPng(const std::filesystem::path& path, const LdrImage& image);

}  // namespace candela::golden
