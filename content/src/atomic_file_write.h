#pragma once
// Crash-safe file replacement: write a temporary file beside the target, fsync it, rename it
// over the target, fsync the directory. Readers see the old or the new file, never a mix.
#include <filesystem>
#include <string_view>

namespace candela::content {

// Returns an empty string on success, else what failed (the target is then unchanged).
std::string writeFileAtomically(const std::filesystem::path& path, std::string_view contents);

}  // namespace candela::content
