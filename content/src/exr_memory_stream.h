#pragma once
// An OpenEXR input stream over bytes already in memory, so a file is read once, its size is
// known (and bounded) before OpenEXR sees it, and fuzzers can feed buffers directly.
#include <OpenEXR/ImfIO.h>

#include <cstddef>
#include <cstdint>
#include <span>

namespace candela::content {

class ExrMemoryStream final : public Imf::IStream {
public:
    ExrMemoryStream(std::span<const std::byte> bytes, const char* name);

    bool read(char c[], int n) override;  // throws Iex::InputExc past the end, as OpenEXR expects
    std::uint64_t tellg() override { return position_; }
    void seekg(std::uint64_t position) override;
    void clear() override {}

private:
    std::span<const std::byte> bytes_;
    std::uint64_t position_ = 0;
};

}  // namespace candela::content
