// glTF images -> Model::images (RGBA8), with the fallback checker for any that fail.
#include "gltf_accessors.h"
#include "gltf_context.h"
#include "gltf_image_callback.h"
#include "image_decoding.h"

namespace candela::content::gltf {

void convertImages(Context& context, const ImageCallbackState& callbackState) {
    const tinygltf::Model& document = context.document;
    context.model.images.reserve(document.images.size());
    for (std::size_t i = 0; i < document.images.size(); ++i) {
        const tinygltf::Image& source = document.images[i];
        const std::string element = elementName("images", i);
        Rgba8Image image;
        std::string problem;
        if (source.bufferView >= 0) {
            std::span<const std::uint8_t> bytes;
            problem = bufferViewBytes(document, source.bufferView, bytes);
            if (problem.empty()) problem = decodeImageRgba8(bytes, image, callbackState.limits);
        } else if (auto it = callbackState.errors.find(static_cast<int>(i));
                   it != callbackState.errors.end()) {
            problem = it->second;
        } else if (source.width > 0 && source.height > 0 && source.component == 4 &&
                   source.image.size() == std::size_t(source.width) * source.height * 4) {
            image.width = static_cast<std::uint32_t>(source.width);
            image.height = static_cast<std::uint32_t>(source.height);
            image.rgba = source.image;
        } else {
            problem = source.uri.empty() ? "image has neither a uri nor a bufferView"
                                         : "cannot read '" + source.uri + "'";
        }
        if (!problem.empty()) {
            context.error(element, problem + "; using the magenta checker");
            image = makeFallbackCheckerImage();
        }
        context.model.images.push_back(std::move(image));
    }
}

std::int32_t fallbackImageIndex(Context& context) {
    if (context.fallbackImage == kNoIndex) {
        context.model.images.push_back(makeFallbackCheckerImage());
        context.fallbackImage = static_cast<std::int32_t>(context.model.images.size() - 1);
    }
    return context.fallbackImage;
}

std::int32_t fallbackTextureIndex(Context& context) {
    if (context.fallbackTexture == kNoIndex) {
        Texture texture;
        texture.name = "fallback checker";
        texture.image = fallbackImageIndex(context);
        texture.sampler.magFilter = Filter::Nearest;  // keep the checker crisp
        context.model.textures.push_back(texture);
        context.fallbackTexture = static_cast<std::int32_t>(context.model.textures.size() - 1);
    }
    return context.fallbackTexture;
}

}  // namespace candela::content::gltf
