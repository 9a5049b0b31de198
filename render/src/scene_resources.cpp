#include "candela/render/scene_resources.h"

#include "candela/render/frame_scene.h"

#include <algorithm>
#include <cstring>
#include <iterator>

#include "candela/render/gpu_context.h"
#include "gpu_material.h"
#include "mesh_vertex.h"
#include "passes/skinning/skinning_bindings.h"
#include "vk/vk_check.h"

namespace candela::render {

namespace {

// Where each material texture slot's texture comes from, in slot order (the order textures
// upload in), and whether it holds normals: a missing normal map binds the flat normal, any
// other missing texture white.
struct TextureSlotSource {
    TextureSlot slot;
    content::TextureRef content::Material::*texture;
    bool normals;
};
constexpr TextureSlotSource kTextureSlotSources[] = {
    {kBaseColorSlot, &content::Material::baseColorTexture, false},
    {kMetallicRoughnessSlot, &content::Material::metallicRoughnessTexture, false},
    {kNormalSlot, &content::Material::normalTexture, true},
    {kOcclusionSlot, &content::Material::occlusionTexture, false},
    {kEmissiveSlot, &content::Material::emissiveTexture, false},
    {kSpecularSlot, &content::Material::specularTexture, false},
    {kSpecularColorSlot, &content::Material::specularColorTexture, false},
    {kAnisotropySlot, &content::Material::anisotropyTexture, false},
    {kClearcoatSlot, &content::Material::clearcoatTexture, false},
    {kClearcoatRoughnessSlot, &content::Material::clearcoatRoughnessTexture, false},
    {kClearcoatNormalSlot, &content::Material::clearcoatNormalTexture, true},
};
static_assert(
    [] {
        if (std::size(kTextureSlotSources) != kTextureSlotCount) return false;
        for (uint32_t i = 0; i < kTextureSlotCount; ++i) {
            if (kTextureSlotSources[i].slot != i) return false;
        }
        return true;
    }(),
    "every texture slot has one source, in slot order");

GpuBuffer uploadBuffer(GpuContext& context, const void* data, VkDeviceSize bytes,
                       VkBufferUsageFlags usage) {
    GpuBuffer staging(context, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                      MemoryLocation::HostVisible);
    std::memcpy(staging.mapped(), data, bytes);
    GpuBuffer buffer(context, bytes, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                     MemoryLocation::Device);
    context.submitAndWait([&](VkCommandBuffer cmd) {
        VkBufferCopy region{0, 0, bytes};
        vkCmdCopyBuffer(cmd, staging.handle(), buffer.handle(), 1, &region);
    });
    return buffer;
}

std::vector<MeshVertex> interleave(const content::Primitive& p) {
    std::vector<MeshVertex> vertices(p.positions.size());
    for (size_t i = 0; i < vertices.size(); ++i) {
        MeshVertex& v = vertices[i];
        std::memcpy(v.position, p.positions[i].data(), sizeof(v.position));
        if (i < p.normals.size()) std::memcpy(v.normal, p.normals[i].data(), sizeof(v.normal));
        if (i < p.tangents.size()) std::memcpy(v.tangent, p.tangents[i].data(), sizeof(v.tangent));
        if (i < p.uv0.size()) std::memcpy(v.uv0, p.uv0[i].data(), sizeof(v.uv0));
        if (i < p.uv1.size()) std::memcpy(v.uv1, p.uv1[i].data(), sizeof(v.uv1));
        if (i < p.colors.size()) {
            std::memcpy(v.color, p.colors[i].data(), sizeof(v.color));
        } else {
            std::fill(std::begin(v.color), std::end(v.color), 1.0f);
        }
    }
    return vertices;
}

// The skinning pass's inputs for an animated primitive (skinning_bindings.h layouts).
void uploadDeformation(GpuContext& context, const content::Primitive& p, bool skinned,
                       GpuMesh& gpu) {
    const size_t count = p.positions.size();
    if (skinned) {
        struct SkinVertex {
            uint32_t joints[4];
            float weights[4];
        };
        std::vector<SkinVertex> skin(count);
        for (size_t v = 0; v < count; ++v) {
            for (int c = 0; c < 4; ++c) {
                skin[v].joints[c] = p.joints[v][c];
                skin[v].weights[c] = v < p.weights.size() ? p.weights[v][c] : 0.0f;
            }
        }
        gpu.skinVertices = uploadBuffer(context, skin.data(), skin.size() * sizeof(SkinVertex),
                                        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    }
    if (!p.morphTargets.empty()) {
        std::vector<glm::vec4> deltas(p.morphTargets.size() * SKINNING_MORPH_ATTRIBUTES * count,
                                      glm::vec4(0.0f));
        for (size_t t = 0; t < p.morphTargets.size(); ++t) {
            const content::MorphTarget& target = p.morphTargets[t];
            const std::vector<content::Float3>* attributes[SKINNING_MORPH_ATTRIBUTES] = {
                &target.positionDeltas, &target.normalDeltas, &target.tangentDeltas};
            // A primitive without tangents keeps zero ones (as content::deformPrimitive).
            const size_t used = p.tangents.size() == count ? SKINNING_MORPH_ATTRIBUTES : 2;
            for (size_t a = 0; a < used; ++a) {
                const std::vector<content::Float3>& d = *attributes[a];
                glm::vec4* out = &deltas[(t * SKINNING_MORPH_ATTRIBUTES + a) * count];
                for (size_t v = 0; v < count && v < d.size(); ++v)
                    out[v] = glm::vec4(d[v][0], d[v][1], d[v][2], 0.0f);
            }
        }
        gpu.morphDeltas = uploadBuffer(context, deltas.data(), deltas.size() * sizeof(glm::vec4),
                                       VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        gpu.morphTargetCount = uint32_t(p.morphTargets.size());
    }
}

uint32_t mipCount(uint32_t width, uint32_t height) {
    uint32_t levels = 1;
    while ((std::max(width, height) >> levels) > 0)
        ++levels;
    return levels;
}

VkFilter toVk(content::Filter f) {
    return f == content::Filter::Nearest ? VK_FILTER_NEAREST : VK_FILTER_LINEAR;
}

VkSamplerAddressMode toVk(content::Wrap w) {
    switch (w) {
        case content::Wrap::ClampToEdge:
            return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        case content::Wrap::MirroredRepeat:
            return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
        case content::Wrap::Repeat:
            break;
    }
    return VK_SAMPLER_ADDRESS_MODE_REPEAT;
}

uint32_t samplerKey(const content::Sampler& s) {
    return uint32_t(s.magFilter) | uint32_t(s.minFilter) << 2 | uint32_t(s.mipFilter) << 4 |
           uint32_t(s.useMipmaps) << 6 | uint32_t(s.wrapS) << 8 | uint32_t(s.wrapT) << 10;
}

content::Rgba8Image solidImage(uint8_t r, uint8_t g, uint8_t b, uint8_t a) {
    content::Rgba8Image image;
    image.width = 1;
    image.height = 1;
    image.rgba = {r, g, b, a};
    return image;
}

// Records mip generation by successive linear blits. Blits filter in linear space even for
// sRGB formats, so colour textures are averaged correctly.
void recordMipChain(VkCommandBuffer cmd, const GpuImage& image) {
    const ImageDesc& d = image.desc();
    auto barrier = [&](uint32_t mip, VkImageLayout from, VkImageLayout to, VkAccessFlags2 src,
                       VkAccessFlags2 dst, VkPipelineStageFlags2 dstStage) {
        VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
        b.srcStageMask = VK_PIPELINE_STAGE_2_TRANSFER_BIT;
        b.srcAccessMask = src;
        b.dstStageMask = dstStage;
        b.dstAccessMask = dst;
        b.oldLayout = from;
        b.newLayout = to;
        b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.image = image.handle();
        b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, mip, 1, 0, 1};
        VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
        dep.imageMemoryBarrierCount = 1;
        dep.pImageMemoryBarriers = &b;
        vkCmdPipelineBarrier2(cmd, &dep);
    };
    int32_t w = int32_t(d.width), h = int32_t(d.height);
    for (uint32_t mip = 1; mip < d.mipLevels; ++mip) {
        barrier(mip - 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                VK_PIPELINE_STAGE_2_TRANSFER_BIT);
        VkImageBlit blit{};
        blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, mip - 1, 0, 1};
        blit.srcOffsets[1] = {w, h, 1};
        w = std::max(1, w / 2);
        h = std::max(1, h / 2);
        blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, mip, 0, 1};
        blit.dstOffsets[1] = {w, h, 1};
        vkCmdBlitImage(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image.handle(),
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_LINEAR);
        barrier(mip - 1, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_2_TRANSFER_READ_BIT,
                VK_ACCESS_2_SHADER_READ_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
    }
    barrier(d.mipLevels - 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_2_TRANSFER_WRITE_BIT,
            VK_ACCESS_2_SHADER_READ_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
}

}  // namespace

SceneResources::SceneResources(GpuContext& context) : context_(context) {
    content::Sampler sampler;
    whiteTexture_ =
        uploadTexture(solidImage(255, 255, 255, 255), content::ColorSpace::Linear, sampler);
    flatNormalTexture_ =
        uploadTexture(solidImage(128, 128, 255, 255), content::ColorSpace::Linear, sampler);
    addMaterial(content::Material{});  // index 0: glTF's default material
}

SceneResources::~SceneResources() {
    for (auto& [key, sampler] : samplers_)
        vkDestroySampler(context_.device(), sampler, nullptr);
}

VkSampler SceneResources::samplerFor(const content::Sampler& s) {
    uint32_t key = samplerKey(s);
    if (auto it = samplers_.find(key); it != samplers_.end()) return it->second;
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = toVk(s.magFilter);
    info.minFilter = toVk(s.minFilter);
    info.mipmapMode = s.mipFilter == content::Filter::Nearest ? VK_SAMPLER_MIPMAP_MODE_NEAREST
                                                              : VK_SAMPLER_MIPMAP_MODE_LINEAR;
    info.addressModeU = toVk(s.wrapS);
    info.addressModeV = toVk(s.wrapT);
    info.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    info.maxLod = s.useMipmaps ? VK_LOD_CLAMP_NONE : 0.0f;
    VkSampler sampler;
    CANDELA_VK_CHECK(vkCreateSampler(context_.device(), &info, nullptr, &sampler));
    samplers_.emplace(key, sampler);
    return sampler;
}

uint32_t SceneResources::uploadTexture(const content::Rgba8Image& image, content::ColorSpace space,
                                       const content::Sampler& sampler) {
    ImageDesc desc;
    desc.format =
        space == content::ColorSpace::Srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
    desc.width = image.width;
    desc.height = image.height;
    desc.mipLevels = mipCount(image.width, image.height);
    desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                 VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    GpuTexture texture{GpuImage(context_, desc), samplerFor(sampler)};
    GpuBuffer staging(context_, image.rgba.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                      MemoryLocation::HostVisible);
    std::memcpy(staging.mapped(), image.rgba.data(), image.rgba.size());
    context_.submitAndWait([&](VkCommandBuffer cmd) {
        transitionImage(cmd, texture.image, VK_IMAGE_LAYOUT_UNDEFINED,
                        VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_NONE, 0,
                        VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {image.width, image.height, 1};
        vkCmdCopyBufferToImage(cmd, staging.handle(), texture.image.handle(),
                               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        recordMipChain(cmd, texture.image);
    });
    textures_.push_back(std::move(texture));
    return uint32_t(textures_.size() - 1);
}

uint32_t SceneResources::addMaterial(const content::Material& material) {
    MaterialBinding binding{};
    for (const TextureSlotSource& source : kTextureSlotSources)
        binding.textures[source.slot] = source.normals ? flatNormalTexture_ : whiteTexture_;
    std::fill(std::begin(binding.layerTextures), std::end(binding.layerTextures), whiteTexture_);
    for (uint32_t layer = 0; layer < 3; ++layer)
        binding.layerTextures[kLayerFirstSlot + layer * kTexturesPerLayer + 2] = flatNormalTexture_;
    return addMaterialWithTextures(material, binding);
}

uint32_t SceneResources::addMaterialWithTextures(const content::Material& material,
                                                 const MaterialBinding& binding) {
    materials_.push_back(material);
    materialBindings_.push_back(binding);
    materialTextureSlots_.push_back(presentTextureSlots(material));
    materialsDirty_ = true;
    return uint32_t(materials_.size() - 1);
}

uint32_t SceneResources::textureFor(const content::Model& model, UploadedModel& uploaded,
                                    const content::TextureRef& ref, uint32_t fallback) {
    if (!ref.present() || ref.texture >= int32_t(model.textures.size())) return fallback;
    const content::Texture& t = model.textures[ref.texture];
    if (t.image < 0 || t.image >= int32_t(model.images.size())) return fallback;
    // One GPU image per (texture, colour space): the same glTF texture may serve an sRGB slot
    // in one material and a linear slot in another, which needs two formats.
    uint64_t key = uint64_t(ref.texture) << 1 | (ref.colorSpace == content::ColorSpace::Srgb);
    auto& images = uploaded.textureImages;
    if (auto it = images.find(key); it != images.end()) return it->second;
    uint32_t index = uploadTexture(model.images[t.image], ref.colorSpace, t.sampler);
    images.emplace(key, index);
    return index;
}

uint32_t SceneResources::addModelMaterial(const content::Model& model, UploadedModel& uploaded,
                                          const content::Material& material) {
    // A layered material's base layer binds as its base textures.
    const content::Material m = content::withBaseLayer(material);
    MaterialBinding binding{};
    for (const TextureSlotSource& source : kTextureSlotSources) {
        binding.textures[source.slot] =
            textureFor(model, uploaded, m.*source.texture,
                       source.normals ? flatNormalTexture_ : whiteTexture_);
    }
    const content::MaterialLayering& layering = material.layering;
    binding.layerTextures[kLayerMaskSlot] =
        layering.maskSource == content::LayerMaskSource::Texture
            ? textureFor(model, uploaded, layering.maskTexture, whiteTexture_)
            : whiteTexture_;
    for (uint32_t layer = 1; layer < content::kMaxMaterialLayers; ++layer) {
        uint32_t* slots = binding.layerTextures + kLayerFirstSlot + (layer - 1) * kTexturesPerLayer;
        static const content::MaterialLayer kNoLayer;
        const content::MaterialLayer& l =
            layer < layering.layers.size() ? layering.layers[layer] : kNoLayer;
        content::TextureRef baseColor = l.baseColorTexture;
        baseColor.colorSpace = content::ColorSpace::Srgb;  // a colour slot, whatever the file says
        slots[0] = textureFor(model, uploaded, baseColor, whiteTexture_);
        slots[1] = textureFor(model, uploaded, l.metallicRoughnessTexture, whiteTexture_);
        slots[2] = textureFor(model, uploaded, l.normalTexture, flatNormalTexture_);
    }
    return addMaterialWithTextures(material, binding);
}

uint32_t SceneResources::addMaterialOverride(const content::Model& model,
                                             const content::Material& material) {
    addModel(model);
    return addModelMaterial(model, models_.at(&model), material);
}

VkBuffer SceneResources::vertexBufferOf(const DrawItem& draw) const {
    return draw.deformedVertices != VK_NULL_HANDLE ? draw.deformedVertices
                                                   : meshes_[draw.mesh].vertices.handle();
}

VkBuffer SceneResources::previousVertexBufferOf(const DrawItem& draw) const {
    return draw.previousDeformedVertices != VK_NULL_HANDLE ? draw.previousDeformedVertices
                                                           : vertexBufferOf(draw);
}

std::pair<glm::vec3, glm::vec3> SceneResources::meshSpaceBounds(const DrawItem& draw) const {
    if (draw.ownBounds) return {draw.boundsCenter, draw.boundsExtent};
    return {meshes_[draw.mesh].boundsCenter, meshes_[draw.mesh].boundsExtent};
}

SceneResources::DeformedVertices SceneResources::deformedVertexBuffers(uint64_t instanceKey,
                                                                       uint32_t mesh,
                                                                       bool continuesLastFrame) {
    const VkDeviceSize bytes =
        std::max<VkDeviceSize>(meshes_[mesh].vertexCount, 1) * sizeof(MeshVertex);
    auto it = deformed_.find(instanceKey);
    if (it == deformed_.end() || it->second.buffers[0].size() != bytes) {
        DeformedInstance instance;
        for (GpuBuffer& buffer : instance.buffers) {
            // Transfer source: tests and tools read the deformed vertices back.
            buffer =
                GpuBuffer(context_, bytes,
                          VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                              VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                          MemoryLocation::Device);
        }
        it = deformed_.insert_or_assign(instanceKey, std::move(instance)).first;
        continuesLastFrame = false;  // nothing was deformed into the new buffers yet
    }
    DeformedInstance& instance = it->second;
    instance.used = true;
    const uint32_t previous = instance.current;
    instance.current ^= 1u;
    const VkBuffer current = instance.buffers[instance.current].handle();
    return {current, continuesLastFrame ? instance.buffers[previous].handle() : current};
}

void SceneResources::releaseUnusedDeformed() {
    std::erase_if(deformed_, [](const auto& entry) { return !entry.second.used; });
    for (auto& [key, deformed] : deformed_)
        deformed.used = false;
}

const GpuBuffer* SceneResources::deformedBuffer(uint64_t instanceKey) const {
    auto it = deformed_.find(instanceKey);
    return it != deformed_.end() ? &it->second.buffers[it->second.current] : nullptr;
}

const UploadedModel& SceneResources::addModel(const content::Model& model) {
    if (auto it = models_.find(&model); it != models_.end()) return it->second;
    UploadedModel uploaded;

    uploaded.firstMaterial = uint32_t(materials_.size());
    for (const content::Material& m : model.materials)
        addModelMaterial(model, uploaded, m);

    for (const content::Mesh& mesh : model.meshes) {
        uploaded.firstPrimitiveOfMesh.push_back(uint32_t(meshes_.size()));
        uploaded.primitiveCountOfMesh.push_back(uint32_t(mesh.primitives.size()));
        for (const content::Primitive& p : mesh.primitives) {
            std::vector<MeshVertex> vertices = interleave(p);
            GpuMesh gpu;
            const bool skinned = !p.joints.empty() && p.joints.size() == p.positions.size();
            const bool deformable = skinned || !p.morphTargets.empty();
            // An animated primitive's vertices are also the skinning pass's storage input.
            gpu.vertices =
                uploadBuffer(context_, vertices.data(), vertices.size() * sizeof(MeshVertex),
                             VK_BUFFER_USAGE_VERTEX_BUFFER_BIT |
                                 (deformable ? VK_BUFFER_USAGE_STORAGE_BUFFER_BIT : 0));
            gpu.vertexCount = uint32_t(p.positions.size());
            if (deformable && !p.positions.empty()) uploadDeformation(context_, p, skinned, gpu);
            // The full list, then each coarser level after it (content/mesh_lods.h).
            std::vector<uint32_t> indices = p.indices;
            gpu.indexCount = uint32_t(p.indices.size());
            gpu.lods[0] = {0, gpu.indexCount, 0.0f};
            for (content::MeshLod& lod : content::buildMeshLods(p)) {
                gpu.lods[gpu.lodCount++] = {uint32_t(indices.size()), uint32_t(lod.indices.size()),
                                            lod.error};
                indices.insert(indices.end(), lod.indices.begin(), lod.indices.end());
            }
            gpu.indices = uploadBuffer(context_, indices.data(), indices.size() * sizeof(uint32_t),
                                       VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
            if (!p.positions.empty()) {
                glm::vec3 lo(p.positions[0][0], p.positions[0][1], p.positions[0][2]);
                glm::vec3 hi = lo;
                for (const auto& position : p.positions) {
                    glm::vec3 v(position[0], position[1], position[2]);
                    lo = glm::min(lo, v);
                    hi = glm::max(hi, v);
                }
                // Morph targets move vertices by up to the sum of each target's deltas (at
                // weights within [0, 1]): the box holds every such pose.
                for (const content::MorphTarget& target : p.morphTargets) {
                    glm::vec3 down(0.0f), up(0.0f);
                    for (const auto& d : target.positionDeltas) {
                        down = glm::min(down, glm::vec3(d[0], d[1], d[2]));
                        up = glm::max(up, glm::vec3(d[0], d[1], d[2]));
                    }
                    lo += down;
                    hi += up;
                }
                gpu.boundsCenter = 0.5f * (lo + hi);
                gpu.boundsExtent = 0.5f * (hi - lo);
            }
            gpu.defaultMaterial = p.material >= 0 && p.material < int32_t(model.materials.size())
                                      ? int32_t(uploaded.firstMaterial + p.material)
                                      : int32_t(defaultMaterial());
            meshes_.push_back(std::move(gpu));
        }
    }
    return models_.emplace(&model, std::move(uploaded)).first->second;
}

const GpuBuffer& SceneResources::materialBuffer() {
    if (materialsDirty_) {
        std::vector<GpuMaterial> packed;
        packed.reserve(materials_.size());
        for (const content::Material& m : materials_)
            packed.push_back(packMaterial(m));
        materialBuffer_ = uploadBuffer(context_, packed.data(), packed.size() * sizeof(GpuMaterial),
                                       VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        materialsDirty_ = false;
    }
    return materialBuffer_;
}

}  // namespace candela::render
