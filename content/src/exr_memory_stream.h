#pragma once
// OpenEXR streams over memory. Input: a file is read once, its size is known (and bounded)
// before OpenEXR sees it, and fuzzers can feed buffers directly. Output: an image is encoded
// whole before the engine's atomic file writer puts it on disk, so a full disk or a failed
// encode never leaves a partial file.
#include <OpenEXR/ImfIO.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

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

class ExrMemoryOutputStream final : public Imf::OStream {
public:
    explicit ExrMemoryOutputStream(const char* name) : Imf::OStream(name) {}

    void write(const char c[], int n) override;
    std::uint64_t tellp() override { return position_; }
    void seekp(std::uint64_t position) override { position_ = position; }

    const std::string& bytes() const { return bytes_; }

private:
    std::string bytes_;
    std::uint64_t position_ = 0;
};

}  // namespace candela::content
