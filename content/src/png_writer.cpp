#include "candela/content/png_writer.h"

#include <string_view>
#include <vector>

#include "candela/content/atomic_file_write.h"

// stb_image_write comes with libstb-dev, which tinygltf already depends on.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

namespace candela::content {

namespace {
void appendBytes(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<unsigned char>*>(context);
    auto* bytes = static_cast<unsigned char*>(data);
    out->insert(out->end(), bytes, bytes + size);
}
}  // namespace

std::string writePng(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
                     int channels, const std::uint8_t* pixels) {
    // Encode to memory first so an encoder failure never leaves a partial file behind; the
    // bytes then go through the engine's one checked, atomic file writer.
    std::vector<unsigned char> encoded;
    if (!stbi_write_png_to_func(appendBytes, &encoded, int(width), int(height), channels, pixels,
                                int(width) * channels)) {
        return path.string() + ": PNG encoding failed";
    }
    return writeFileAtomically(
        path, std::string_view(reinterpret_cast<const char*>(encoded.data()), encoded.size()));
}

}  // namespace candela::content
