#include "gltf_image_callback.h"

namespace candela::content::gltf {

bool decodeImageFromUri(tinygltf::Image* image, int imageIndex, std::string* /*error*/,
                        std::string* /*warning*/, int /*requestedWidth*/, int /*requestedHeight*/,
                        const unsigned char* bytes, int size, void* state) {
    auto& callbackState = *static_cast<ImageCallbackState*>(state);
    if (image->bufferView >= 0) return true;  // decoded later, after bounds checks
    if (bytes == nullptr || size <= 0) {
        callbackState.errors[imageIndex] = "image data is empty";
        return true;
    }
    Rgba8Image decoded;
    std::string problem =
        decodeImageRgba8({bytes, static_cast<std::size_t>(size)}, decoded, callbackState.limits);
    if (!problem.empty()) {
        callbackState.errors[imageIndex] = problem;
        return true;
    }
    image->width = static_cast<int>(decoded.width);
    image->height = static_cast<int>(decoded.height);
    image->component = 4;
    image->bits = 8;
    image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image->image = std::move(decoded.rgba);
    return true;
}

}  // namespace candela::content::gltf
