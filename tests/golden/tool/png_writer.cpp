// writeLdrPng, and the one translation unit of this tool that compiles stb_image_write.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

#include "image_files.h"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

namespace candela::golden {

namespace {
void appendBytes(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<unsigned char>*>(context);
    auto* bytes = static_cast<unsigned char*>(data);
    out->insert(out->end(), bytes, bytes + size);
}
}  // namespace

std::string writeLdrPng(const std::filesystem::path& path, const LdrImage& image) {
    std::vector<unsigned char> encoded;
    if (!stbi_write_png_to_func(appendBytes, &encoded, int(image.width), int(image.height), 3,
                                image.rgb.data(), int(image.width * 3))) {
        return path.string() + ": PNG encoding failed";
    }
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) return path.string() + ": cannot open for writing: " + std::strerror(errno);
    std::size_t written = std::fwrite(encoded.data(), 1, encoded.size(), file);
    bool closed = std::fclose(file) == 0;
    if (written != encoded.size() || !closed) return path.string() + ": write failed";
    return {};
}

}  // namespace candela::golden
