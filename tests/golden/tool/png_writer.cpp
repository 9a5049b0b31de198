// writeLdrPng: the golden tool's images through the engine's PNG writer.
#include "candela/content/png_writer.h"
#include "image_files.h"

namespace candela::golden {

std::string writeLdrPng(const std::filesystem::path& path, const LdrImage& image) {
    return content::writePng(path, image.width, image.height, 3, image.rgb.data());
}

}  // namespace candela::golden
