// glTF textures and samplers -> Model::textures.
#include "gltf_context.h"

namespace candela::content::gltf {
namespace {

Wrap toWrap(int mode) {
    switch (mode) {
        case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE:
            return Wrap::ClampToEdge;
        case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT:
            return Wrap::MirroredRepeat;
        default:
            return Wrap::Repeat;
    }
}

Sampler toSampler(const tinygltf::Sampler& source) {
    Sampler sampler;
    sampler.magFilter =
        source.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST ? Filter::Nearest : Filter::Linear;
    switch (source.minFilter) {
        case TINYGLTF_TEXTURE_FILTER_NEAREST:
            sampler.minFilter = Filter::Nearest;
            sampler.useMipmaps = false;
            break;
        case TINYGLTF_TEXTURE_FILTER_LINEAR:
            sampler.minFilter = Filter::Linear;
            sampler.useMipmaps = false;
            break;
        case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST:
            sampler.minFilter = Filter::Nearest;
            sampler.mipFilter = Filter::Nearest;
            break;
        case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST:
            sampler.minFilter = Filter::Linear;
            sampler.mipFilter = Filter::Nearest;
            break;
        case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR:
            sampler.minFilter = Filter::Nearest;
            sampler.mipFilter = Filter::Linear;
            break;
        default:  // LINEAR_MIPMAP_LINEAR, and "undefined" where glTF leaves the choice to us
            break;
    }
    sampler.wrapS = toWrap(source.wrapS);
    sampler.wrapT = toWrap(source.wrapT);
    return sampler;
}

}  // namespace

void convertTextures(Context& context) {
    const tinygltf::Model& document = context.document;
    for (std::size_t i = 0; i < document.textures.size(); ++i) {
        const tinygltf::Texture& source = document.textures[i];
        const std::string element = elementName("textures", i);
        Texture texture;
        texture.name = source.name;
        if (source.sampler >= 0) {
            if (validIndex(source.sampler, document.samplers)) {
                texture.sampler =
                    toSampler(document.samplers[static_cast<std::size_t>(source.sampler)]);
            } else {
                context.error(element, "sampler " + std::to_string(source.sampler) +
                                           " does not exist; using the default sampler");
            }
        }
        if (validIndex(source.source, context.model.images)) {
            texture.image = source.source;
        } else {
            context.error(element, source.source < 0
                                       ? "has no source image (extension-only sources such as "
                                         "KTX2/WebP are not supported); using the magenta checker"
                                       : "source image " + std::to_string(source.source) +
                                             " does not exist; using the magenta checker");
            texture.image = fallbackImageIndex(context);
        }
        context.model.textures.push_back(std::move(texture));
    }
}

}  // namespace candela::content::gltf
