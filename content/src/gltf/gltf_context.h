#pragma once
// State shared by the glTF conversion steps: the parsed document, where messages go, the
// options, and the model being filled.
#include <tiny_gltf.h>

#include <string>
#include <vector>

#include "candela/content/diagnostics.h"
#include "candela/content/gltf_loader.h"
#include "candela/content/model.h"

namespace candela::content::gltf {

struct Context {
    const tinygltf::Model& document;
    std::string file;
    Diagnostics& diagnostics;
    const GltfLoadOptions& options;
    Model& model;
    // Appended after all glTF images/textures on first need, so glTF indices stay valid.
    std::int32_t fallbackImage = kNoIndex;
    std::int32_t fallbackTexture = kNoIndex;

    void error(const std::string& element, const std::string& message) {
        diagnostics.error(file, element, message);
    }
    void warning(const std::string& element, const std::string& message) {
        diagnostics.warning(file, element, message);
    }
};

// "meshes[3]"
inline std::string elementName(const char* array, std::size_t index) {
    return std::string(array) + "[" + std::to_string(index) + "]";
}

template <typename T>
bool validIndex(int index, const std::vector<T>& array) {
    return index >= 0 && static_cast<std::size_t>(index) < array.size();
}

// The magenta checker image, appended to Model::images on first use (after all glTF images).
std::int32_t fallbackImageIndex(Context& context);
// A texture over the checker, appended to Model::textures on first use (after all glTF
// textures, so call only once convertTextures() is done).
std::int32_t fallbackTextureIndex(Context& context);

struct ImageCallbackState;
void convertImages(Context& context, const ImageCallbackState& callbackState);  // gltf_images.cpp
void convertTextures(Context& context);                                         // gltf_textures.cpp
void convertMaterials(Context& context);         // gltf_materials.cpp
void convertLightsAndCameras(Context& context);  // gltf_lights_cameras.cpp
void convertMeshes(Context& context);            // gltf_meshes.cpp
void convertNodes(Context& context);             // gltf_nodes.cpp
void convertSkins(Context& context);             // gltf_skins.cpp (after nodes)
void convertAnimations(Context& context);        // gltf_animations.cpp (after skins)

struct AccessorLimits;
// gltf_mesh_deformation.cpp: JOINTS_n/WEIGHTS_n and morph targets of one primitive.
void readSkinAttributes(Context& context, const std::string& element,
                        const tinygltf::Primitive& source, std::size_t vertexCount,
                        const AccessorLimits& limits, Primitive& primitive);
void readMorphTargets(Context& context, const std::string& element,
                      const tinygltf::Primitive& source, std::size_t vertexCount,
                      const AccessorLimits& limits, Primitive& primitive);
// A mesh's or node's default morph `weights`: one that is NaN/Inf or beyond 1e9 is 0, with a
// warning naming `element` and its index.
std::vector<float> readMorphWeights(Context& context, const std::string& element,
                                    const std::vector<double>& weights);

}  // namespace candela::content::gltf
