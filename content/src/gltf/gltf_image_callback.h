#pragma once
// tinygltf's image hook. tinygltf hands images stored in bufferViews to the hook without
// checking the view against its buffer, so those are left for convertImages() to decode with
// checked bounds; images from URIs (external files, data URIs) are decoded here.
#include <tiny_gltf.h>

#include <map>
#include <string>

#include "image_decoding.h"

namespace candela::content::gltf {

struct ImageCallbackState {
    ImageDecodeLimits limits;
    std::map<int, std::string> errors;  // image index -> why decoding failed
};

// Always returns true: a bad image must not abort the whole glTF load.
bool decodeImageFromUri(tinygltf::Image* image, int imageIndex, std::string* error,
                        std::string* warning, int requestedWidth, int requestedHeight,
                        const unsigned char* bytes, int size, void* state);

}  // namespace candela::content::gltf
