// Float RGB EXR writing, used by frame captures and golden-image diffs.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>

#include <exception>
#include <limits>

#include "candela/content/atomic_file_write.h"
#include "candela/content/exr_image.h"
#include "exr_memory_stream.h"

namespace candela::content {

std::string writeExrRgbFloat(const std::filesystem::path& path, std::uint32_t width,
                             std::uint32_t height, const float* rgb) {
    // Every message starts with the path, as the engine's other file writers' do.
    if (width == 0 || height == 0) return path.string() + ": cannot write a zero-sized image";
    if (rgb == nullptr) return path.string() + ": no pixel data to write";
    constexpr auto maxInt = static_cast<std::uint32_t>(std::numeric_limits<int>::max());
    // OpenEXR addresses pixels with int; keep the byte strides representable too.
    if (width > maxInt / 12 || height > maxInt) {
        return path.string() + ": the image is too large for OpenEXR";
    }
    try {
        Imf::Header header(static_cast<int>(width), static_cast<int>(height));
        header.compression() = Imf::ZIP_COMPRESSION;
        for (const char* channel : {"R", "G", "B"}) {
            header.channels().insert(channel, Imf::Channel(Imf::FLOAT));
        }
        Imf::FrameBuffer frameBuffer;
        const std::size_t xStride = 3 * sizeof(float);
        const std::size_t yStride = xStride * width;
        // OpenEXR's Slice wants a non-const pointer but only reads through it when writing.
        char* base = reinterpret_cast<char*>(const_cast<float*>(rgb));
        frameBuffer.insert("R", Imf::Slice(Imf::FLOAT, base, xStride, yStride));
        frameBuffer.insert("G", Imf::Slice(Imf::FLOAT, base + sizeof(float), xStride, yStride));
        frameBuffer.insert("B", Imf::Slice(Imf::FLOAT, base + 2 * sizeof(float), xStride, yStride));
        // Encoded whole in memory, then written atomically: the file is complete or absent.
        ExrMemoryOutputStream stream(path.string().c_str());
        {
            Imf::OutputFile file(stream, header);
            file.setFrameBuffer(frameBuffer);
            file.writePixels(static_cast<int>(height));
        }  // the destructor writes the line offset table
        return writeFileAtomically(path, stream.bytes());
    } catch (const std::exception& e) {
        return path.string() + ": cannot encode EXR: " + e.what();
    }
}

}  // namespace candela::content
