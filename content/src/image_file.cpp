#include "candela/content/image_file.h"

#include "candela/content/file_bytes.h"
#include "image_decoding.h"

namespace candela::content {

std::optional<Rgba8Image> loadImageFile(const std::filesystem::path& path,
                                        Diagnostics& diagnostics) {
    const FileBytes file = readFileBytes(path, kMaxImageFileBytes);
    if (!file.error.empty()) {
        diagnostics.error(path.string(), "", "cannot read image: " + file.error);
        return std::nullopt;
    }
    Rgba8Image image;
    const auto* data = reinterpret_cast<const std::uint8_t*>(file.bytes.data());
    if (std::string problem = decodeImageRgba8({data, file.bytes.size()}, image);
        !problem.empty()) {
        diagnostics.error(path.string(), "", "cannot decode image: " + problem);
        return std::nullopt;
    }
    return image;
}

}  // namespace candela::content
