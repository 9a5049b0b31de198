#include "image_files.h"

#include <fstream>
#include <iterator>
#include <vector>

#include "candela/content/exr_image.h"

// stb_image is compiled into candela_content (STBI_NO_STDIO, so from memory only).
extern "C" unsigned char* stbi_load_from_memory(const unsigned char* buffer, int len, int* x,
                                                int* y, int* comp, int req_comp);
extern "C" void stbi_image_free(void* data);
extern "C" const char* stbi_failure_reason(void);

namespace candela::golden {

std::optional<LoadedHdr> readHdrExr(const std::filesystem::path& path, std::string& error) {
    content::Diagnostics diagnostics;
    std::optional<content::ExrImage> exr = content::readExrImage(path, diagnostics);
    if (!exr) {
        error = diagnostics.toString();
        if (error.empty()) error = path.string() + ": cannot read EXR";
        return std::nullopt;
    }
    LoadedHdr loaded;
    loaded.nonFiniteTexels = exr->replacedNonFiniteTexels;
    loaded.image.width = exr->image.width;
    loaded.image.height = exr->image.height;
    loaded.image.rgb.resize(loaded.image.pixelCount() * 3);
    for (std::size_t i = 0; i < loaded.image.pixelCount(); ++i) {
        for (std::size_t c = 0; c < 3; ++c) {
            loaded.image.rgb[i * 3 + c] = exr->image.rgba[i * 4 + c];
        }
    }
    return loaded;
}

std::optional<LdrImage> readLdrPng(const std::filesystem::path& path, std::string& error) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        error = path.string() + ": cannot open";
        return std::nullopt;
    }
    std::vector<unsigned char> bytes{std::istreambuf_iterator<char>(in),
                                     std::istreambuf_iterator<char>()};
    int width = 0, height = 0, channels = 0;
    unsigned char* pixels =
        stbi_load_from_memory(bytes.data(), int(bytes.size()), &width, &height, &channels, 3);
    if (!pixels) {
        error = path.string() + ": cannot decode PNG: " + stbi_failure_reason();
        return std::nullopt;
    }
    LdrImage image;
    image.width = std::uint32_t(width);
    image.height = std::uint32_t(height);
    image.rgb.assign(pixels, pixels + image.pixelCount() * 3);
    stbi_image_free(pixels);
    return image;
}

std::string writeHdrExr(const std::filesystem::path& path, const HdrImage& image) {
    return content::writeExrRgbFloat(path, image.width, image.height, image.rgb.data());
}

}  // namespace candela::golden
