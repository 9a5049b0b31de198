#include "exr_memory_stream.h"

#include <Iex.h>

#include <cstring>

namespace candela::content {

ExrMemoryStream::ExrMemoryStream(std::span<const std::byte> bytes, const char* name)
    : Imf::IStream(name), bytes_(bytes) {}

bool ExrMemoryStream::read(char c[], int n) {
    if (n < 0 || position_ > bytes_.size() ||
        static_cast<std::uint64_t>(n) > bytes_.size() - position_) {
        throw Iex::InputExc("unexpected end of file");
    }
    std::memcpy(c, bytes_.data() + position_, static_cast<std::size_t>(n));
    position_ += static_cast<std::uint64_t>(n);
    return position_ < bytes_.size();
}

void ExrMemoryStream::seekg(std::uint64_t position) {
    // Seeking past the end is legal; the next read throws.
    position_ = position;
}

}  // namespace candela::content
