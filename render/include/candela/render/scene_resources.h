#pragma once
// GPU copies of a scene's meshes, materials and textures. A model added twice is uploaded once
// (keyed by its address); within a model, a texture used by several materials is one image.
#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <span>
#include <unordered_map>
#include <vector>

#include "candela/content/model.h"
#include "candela/render/environment.h"
#include "candela/render/gpu_buffer.h"
#include "candela/render/gpu_image.h"

namespace candela::render {

class GpuContext;

struct GpuMesh {
    GpuBuffer vertices;  // interleaved MeshVertex
    GpuBuffer indices;   // uint32
    uint32_t indexCount = 0;
    int32_t defaultMaterial = -1;  // the primitive's material in SceneResources, -1: default
    glm::vec3 boundsCenter{0.0f};  // of the positions' box, mesh space (transparency sorting)
    glm::vec3 boundsExtent{0.0f};  // half its size (shadow caster culling)
};

struct GpuTexture {
    GpuImage image;
    VkSampler sampler = VK_NULL_HANDLE;  // owned by the sampler cache
};

// Where a model's pieces landed: mesh index of primitive p of glTF mesh m is
// firstPrimitiveOfMesh[m] + p.
struct UploadedModel {
    std::vector<uint32_t> firstPrimitiveOfMesh;
    std::vector<uint32_t> primitiveCountOfMesh;
    uint32_t firstMaterial = 0;
    std::unordered_map<uint64_t, uint32_t> textureImages;  // (texture, sRGB?) -> texture
};

// Texture slots of a material, in binding order of the G-buffer pass.
enum TextureSlot : uint32_t {
    kBaseColorSlot,
    kMetallicRoughnessSlot,
    kNormalSlot,
    kOcclusionSlot,
    kEmissiveSlot,
    kSpecularSlot,            // KHR_materials_specular specularTexture (A)
    kSpecularColorSlot,       // KHR_materials_specular specularColorTexture (RGB, sRGB)
    kAnisotropySlot,          // KHR_materials_anisotropy (RG direction, B strength)
    kClearcoatSlot,           // KHR_materials_clearcoat clearcoatTexture (R)
    kClearcoatRoughnessSlot,  // KHR_materials_clearcoat clearcoatRoughnessTexture (G)
    kClearcoatNormalSlot,     // KHR_materials_clearcoat clearcoatNormalTexture
    kTextureSlotCount
};

// Textures of a layered material beyond the slots above (content::MaterialLayering): the mask,
// then base colour, metallic-roughness and normal of layers 1, 2 and 3. Only the G-buffer
// pass's layered variant binds them.
enum LayerTextureSlot : uint32_t {
    kLayerMaskSlot,
    kLayerFirstSlot,  // layer i (1..3), texture t (0 base colour, 1 metal-rough, 2 normal):
                      // kLayerFirstSlot + (i - 1) * kTexturesPerLayer + t
    kTexturesPerLayer = 3,
    kLayerTextureSlotCount = kLayerFirstSlot + 3 * kTexturesPerLayer,
};

struct MaterialBinding {
    uint32_t textures[kTextureSlotCount];  // indices into SceneResources textures
    uint32_t layerTextures[kLayerTextureSlotCount];
};

class SceneResources {
public:
    explicit SceneResources(GpuContext& context);
    ~SceneResources();
    SceneResources(const SceneResources&) = delete;
    SceneResources& operator=(const SceneResources&) = delete;

    const UploadedModel& addModel(const content::Model& model);
    uint32_t addMaterial(const content::Material& material);  // with no textures
    // A material replacing one of `model`'s (scene-file override); its texture indices refer
    // to the model's textures, shared with the model's own materials.
    uint32_t addMaterialOverride(const content::Model& model, const content::Material& material);

    const GpuMesh& mesh(uint32_t index) const { return meshes_[index]; }
    // The vertex buffer a geometry pass binds for `draw`: its deformed vertices when animated,
    // else the mesh's.
    VkBuffer vertexBufferOf(const struct DrawItem& draw) const;
    // The buffer a mesh pass binds as gbuffer.vert's previous-position stream (binding 1):
    // an animated draw's last-frame deformed vertices, else the same as vertexBufferOf.
    VkBuffer previousVertexBufferOf(const struct DrawItem& draw) const;

    // An animated instance's vertex buffers for one frame: this frame's deformed vertices and
    // last frame's (the motion vectors' previous positions).
    struct DeformedVertices {
        VkBuffer current = VK_NULL_HANDLE;
        VkBuffer previous = VK_NULL_HANDLE;
    };
    // Animated instances (skins, morph targets): writes this frame's deformed positions and
    // normals of `primitive` into one of the instance's two host-visible vertex buffers (made
    // on first use for `instanceKey` with the primitive's other attributes); the other keeps
    // last frame's, and the two swap every call. `continuesLastFrame`: the instance was
    // deformed last frame, so the other buffer holds its previous positions; when false (new,
    // or not drawn last frame) previous is current: no deformation motion. The frame waits for
    // its submission before the next one is extracted, so two buffers per instance are enough.
    // Buffers live until the SceneResources goes (a world swap).
    DeformedVertices writeDeformedVertices(uint64_t instanceKey,
                                           const content::Primitive& primitive,
                                           std::span<const content::Float3> positions,
                                           std::span<const content::Float3> normals,
                                           bool continuesLastFrame = false);
    uint32_t deformedInstanceCount() const { return uint32_t(deformed_.size()); }
    uint32_t meshCount() const { return uint32_t(meshes_.size()); }
    uint32_t materialCount() const { return uint32_t(materialBindings_.size()); }
    uint32_t defaultMaterial() const { return 0; }
    const GpuTexture& texture(uint32_t index) const { return textures_[index]; }
    const MaterialBinding& materialBinding(uint32_t material) const {
        return materialBindings_[material];
    }
    const content::Material& material(uint32_t index) const { return materials_[index]; }
    // std430 array of GpuMaterial; rebuilt when materials were added since the last call.
    const GpuBuffer& materialBuffer();

    // The scene's sky: lights every surface (image-based lighting) and fills the background.
    // Null: no environment light, background is FrameInputs::clearRadiance. Shared, so scenes
    // reloaded under the same sky (the editor) keep its precomputed cubes.
    void setEnvironment(std::shared_ptr<const Environment> environment) {
        environment_ = std::move(environment);
    }
    const Environment* environment() const { return environment_.get(); }

private:
    std::shared_ptr<const Environment> environment_;

    uint32_t uploadTexture(const content::Rgba8Image& image, content::ColorSpace space,
                           const content::Sampler& sampler);
    uint32_t addMaterialWithTextures(const content::Material& material,
                                     const MaterialBinding& binding);
    uint32_t addModelMaterial(const content::Model& model, UploadedModel& uploaded,
                              const content::Material& material);
    uint32_t textureFor(const content::Model& model, UploadedModel& uploaded,
                        const content::TextureRef& ref, uint32_t fallback);
    VkSampler samplerFor(const content::Sampler& sampler);

    GpuContext& context_;
    std::vector<GpuMesh> meshes_;
    std::vector<GpuTexture> textures_;
    std::vector<content::Material> materials_;
    std::vector<MaterialBinding> materialBindings_;
    std::unordered_map<const content::Model*, UploadedModel> models_;
    // Per animated instance: two vertex buffers, this frame's at `current`, last frame's at
    // the other (swapped by writeDeformedVertices).
    struct DeformedInstance {
        std::array<GpuBuffer, 2> buffers;
        uint32_t current = 0;
    };
    std::unordered_map<uint64_t, DeformedInstance> deformed_;
    std::unordered_map<uint32_t, VkSampler> samplers_;
    GpuBuffer materialBuffer_;
    bool materialsDirty_ = true;
    uint32_t whiteTexture_ = 0;
    uint32_t flatNormalTexture_ = 0;
};

}  // namespace candela::render
