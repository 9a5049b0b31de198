#include "file_bytes.h"

#include <fstream>
#include <system_error>

namespace candela::content {

FileBytes readFileBytes(const std::filesystem::path& path, std::uint64_t maxBytes) {
    FileBytes result;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        result.error = ec ? "cannot open: " + ec.message() : "no such file";
        return result;
    }
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) {
        result.error = "cannot read size: " + ec.message();
        return result;
    }
    if (size > maxBytes) {
        result.error = "file is " + std::to_string(size) + " bytes, over the limit of " +
                       std::to_string(maxBytes);
        return result;
    }
    std::ifstream stream(path, std::ios::binary);
    if (!stream) {
        result.error = "cannot open for reading";
        return result;
    }
    result.bytes.resize(static_cast<std::size_t>(size));
    stream.read(reinterpret_cast<char*>(result.bytes.data()), static_cast<std::streamsize>(size));
    if (static_cast<std::uintmax_t>(stream.gcount()) != size) {
        result.bytes.clear();
        result.error = "short read";
    }
    return result;
}

}  // namespace candela::content
