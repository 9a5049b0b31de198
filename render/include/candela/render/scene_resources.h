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
#include <utility>
#include <vector>

#include "candela/content/mesh_lods.h"
#include "candela/content/model.h"
#include "candela/render/environment.h"
#include "candela/render/gpu_buffer.h"
#include "candela/render/gpu_image.h"

namespace candela::render {

class GpuContext;

struct GpuMesh {
    GpuBuffer vertices;       // interleaved MeshVertex
    GpuBuffer indices;        // uint32
    uint32_t indexCount = 0;  // level 0's: the full triangle list
    // Levels of detail (content::buildMeshLods): level 0 the full list, then coarser ones over
    // the same vertices, all in `indices` one after another; each level's error is the
    // distance (metres, mesh space) its surface may lie from the full one.
    struct Lod {
        uint32_t firstIndex = 0;
        uint32_t indexCount = 0;
        float error = 0.0f;
    };
    std::array<Lod, content::kMeshLodMaxLevels> lods{};
    uint32_t lodCount = 1;
    int32_t defaultMaterial = -1;  // the primitive's material in SceneResources, -1: default
    // Of the positions' box, mesh space (transparency sorting, shadow caster culling); with
    // morph targets, grown to hold every weight combination in [0, 1].
    glm::vec3 boundsCenter{0.0f};
    glm::vec3 boundsExtent{0.0f};  // half its size
    // Animated primitives (skins, morph targets) only: what the skinning pass reads besides
    // `vertices` (which then also has storage usage). Layouts: passes/skinning/skinning_bindings.h.
    uint32_t vertexCount = 0;
    GpuBuffer skinVertices;  // per vertex uvec4 joints + vec4 weights; empty: not skinned
    GpuBuffer morphDeltas;   // vec4 per (target, attribute, vertex); empty: no targets
    uint32_t morphTargetCount = 0;
    bool deformable() const { return skinVertices.handle() || morphTargetCount > 0; }
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
    // The box (centre, half extent, mesh space) a pass culls or sorts `draw` by: a skinned
    // draw's own (this frame's pose), else its mesh's.
    std::pair<glm::vec3, glm::vec3> meshSpaceBounds(const DrawItem& draw) const;

    // An animated instance's vertex buffers for one frame: the one the skinning pass deforms
    // into this frame, and last frame's (the motion vectors' previous positions).
    struct DeformedVertices {
        VkBuffer current = VK_NULL_HANDLE;
        VkBuffer previous = VK_NULL_HANDLE;
    };
    // Animated instances (skins, morph targets): two device-local vertex buffers (storage +
    // vertex usage, mesh layout) per instance `instanceKey` (unique per instance and primitive),
    // made on first use, that swap every call: `current` is the one the skinning pass deforms
    // `mesh` into this frame, the other keeps last frame's vertices. `continuesLastFrame`: the
    // instance was deformed last frame, so `previous` is the other buffer; when false (new, or
    // not drawn last frame) previous is current: no deformation motion. A frame waits for the
    // previous one, so two buffers per instance are enough. Buffers not asked for in a frame
    // are freed at the next releaseUnusedDeformed().
    DeformedVertices deformedVertexBuffers(uint64_t instanceKey, uint32_t mesh,
                                           bool continuesLastFrame);
    // Frees the deformed buffers no deformedVertexBuffers() call asked for since the last call
    // (destroyed or no longer animated entities); call once per frame, before extraction, when
    // no frame that drew them is still in flight.
    void releaseUnusedDeformed();
    // This frame's deformed buffer of `instanceKey`, or null (tests read it back).
    const GpuBuffer* deformedBuffer(uint64_t instanceKey) const;
    uint32_t deformedInstanceCount() const { return uint32_t(deformed_.size()); }
    uint32_t meshCount() const { return uint32_t(meshes_.size()); }
    uint32_t materialCount() const { return uint32_t(materialBindings_.size()); }
    uint32_t defaultMaterial() const { return 0; }
    const GpuTexture& texture(uint32_t index) const { return textures_[index]; }
    const MaterialBinding& materialBinding(uint32_t material) const {
        return materialBindings_[material];
    }
    const content::Material& material(uint32_t index) const { return materials_[index]; }
    // Bit i: the material's texture slot i is present (the G-buffer pipeline it draws with),
    // found once when the material is added.
    uint32_t materialTextureSlots(uint32_t index) const { return materialTextureSlots_[index]; }
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
    std::vector<uint32_t> materialTextureSlots_;  // per material, presentTextureSlots
    std::unordered_map<const content::Model*, UploadedModel> models_;
    // Per animated instance: two vertex buffers, this frame's at `current`, last frame's at
    // the other (swapped by deformedVertexBuffers).
    struct DeformedInstance {
        std::array<GpuBuffer, 2> buffers;
        uint32_t current = 0;
        bool used = true;  // asked for since the last releaseUnusedDeformed()
    };
    std::unordered_map<uint64_t, DeformedInstance> deformed_;
    std::unordered_map<uint32_t, VkSampler> samplers_;
    GpuBuffer materialBuffer_;
    bool materialsDirty_ = true;
    uint32_t whiteTexture_ = 0;
    uint32_t flatNormalTexture_ = 0;
};

}  // namespace candela::render
