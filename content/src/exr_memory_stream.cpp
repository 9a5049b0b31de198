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

void ExrMemoryOutputStream::write(const char c[], int n) {
    if (n <= 0) return;
    const auto count = static_cast<std::size_t>(n);
    // OpenEXR seeks back to patch the line offset table, so writes may land inside the data.
    if (position_ + count > bytes_.size())
        bytes_.resize(static_cast<std::size_t>(position_) + count);
    std::memcpy(bytes_.data() + position_, c, count);
    position_ += count;
}

}  // namespace candela::content
