#pragma once
// Reads a whole file into memory with an upper bound, so a huge or special file (a FIFO, a
// device) cannot make a loader allocate without limit.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace candela::content {

struct FileBytes {
    std::vector<std::byte> bytes;
    std::string error;  // empty when the read succeeded
};

FileBytes readFileBytes(const std::filesystem::path& path, std::uint64_t maxBytes);

}  // namespace candela::content
