// Issue 20: the skinning compute pass (render/src/passes/skinning) against the CPU reference,
// content::deformPrimitive. The Fox's Walk clip at ten times: the GPU-deformed positions are
// read back and must lie within 1e-4 of the CPU's (the bound, in the file's units,
// although the Fox is about 150 of them long); normals and tangents too, as directions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "candela/content/animation_systems.h"
#include "candela/content/components/animation.h"
#include "candela/content/gltf_loader.h"
#include "candela/content/model_instantiation.h"
#include "candela/content/skinning.h"
#include "candela/ecs/transform_propagation.h"
#include "candela/render/gpu_buffer.h"
#include "candela/render/scene_resources.h"
#include "mesh_vertex.h"
#include "offscreen_frame.h"
#include "passes/skinning/skinning_pass.h"
#include "vk/memory_barrier.h"

using namespace candela;
using namespace candela::render;

namespace {

content::Model loadModel(const std::string& name) {
    content::Diagnostics diagnostics;
    auto loaded = content::loadGltf(
        std::filesystem::path(CANDELA_SHARED_ASSETS) / "models" / name / (name + ".glb"),
        diagnostics);
    EXPECT_TRUE(loaded && !diagnostics.hasErrors()) << diagnostics.toString();
    return loaded ? std::move(*loaded) : content::Model{};
}

// Deforms on the device and copies the result to a host-visible buffer (the frame graph
// places this barrier in a frame; here the test records it).
std::vector<MeshVertex> deformOnDevice(SkinningPass& pass, const GpuMesh& mesh,
                                       const SkinningPass::Pose& pose, const GpuBuffer& target) {
    GpuBuffer readback(test::sharedContext(), target.size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                       MemoryLocation::HostVisible);
    test::sharedContext().submitAndWait([&](VkCommandBuffer cmd) {
        pass.recordDeform(cmd, mesh, pose, target.handle());
        memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                      VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                      VK_ACCESS_2_TRANSFER_READ_BIT);
        const VkBufferCopy region{0, 0, target.size()};
        vkCmdCopyBuffer(cmd, target.handle(), readback.handle(), 1, &region);
    });
    std::vector<MeshVertex> vertices(mesh.vertexCount);
    std::memcpy(vertices.data(), readback.mapped(), vertices.size() * sizeof(MeshVertex));
    return vertices;
}

float distance3(const float* a, const float* b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                     (a[2] - b[2]) * (a[2] - b[2]));
}

}  // namespace

TEST(GpuSkinning, FoxWalkMatchesTheCpuReferenceAtTenTimes) {
    const content::Model fox = loadModel("Fox");
    ecs::Registry registry;
    ecs::JobSystem jobs{1};
    ecs::Entity playerEntity = ecs::kNullEntity;
    for (ecs::Entity e : content::instantiateModel(registry, fox))
        if (registry.has<content::AnimationPlayer>(e)) playerEntity = e;
    ASSERT_NE(playerEntity, ecs::kNullEntity);
    auto& player = registry.get<content::AnimationPlayer>(playerEntity);
    const int32_t walk = player.findClip("Walk");
    ASSERT_GE(walk, 0);
    player.play(walk);
    player.playing = false;  // scrubbed: the time is set directly

    int32_t meshNode = -1;
    for (size_t n = 0; n < fox.nodes.size(); ++n)
        if (fox.nodes[n].skin == 0) meshNode = int32_t(n);
    ASSERT_GE(meshNode, 0);
    const int32_t meshIndex = fox.nodes[size_t(meshNode)].mesh;
    const content::Primitive& primitive = fox.meshes[size_t(meshIndex)].primitives[0];
    ASSERT_FALSE(primitive.joints.empty());

    SceneResources resources(test::sharedContext());
    const UploadedModel& uploaded = resources.addModel(fox);
    const uint32_t meshId = uploaded.firstPrimitiveOfMesh[size_t(meshIndex)];
    const GpuMesh& mesh = resources.mesh(meshId);
    ASSERT_TRUE(mesh.deformable());
    ASSERT_EQ(mesh.vertexCount, primitive.positions.size());
    resources.deformedVertexBuffers(1, meshId, false);
    const GpuBuffer& target = *resources.deformedBuffer(1);
    SkinningPass pass(test::sharedContext());

    const content::AnimationClip& clip = fox.animations[size_t(walk)];
    const auto& skin = registry.get<content::Skin>(player.nodeEntities[size_t(meshNode)]);
    content::DeformedVertices cpu;
    float worstPosition = 0.0f, worstNormal = 0.0f, largestMotion = 0.0f;
    for (int step = 0; step < 10; ++step) {
        player.time = clip.duration * (0.05f + 0.1f * float(step));
        content::advanceAnimationPlayers(registry, jobs, 0.0f);
        ecs::propagateTransforms(registry);
        content::updateSkins(registry, jobs);
        ASSERT_EQ(skin.jointMatrices.size(), fox.skins[0].joints.size());

        std::vector<glm::mat4> joints(skin.jointMatrices.size());
        for (size_t j = 0; j < joints.size(); ++j)
            std::memcpy(&joints[j][0][0], skin.jointMatrices[j].m, sizeof(glm::mat4));
        pass.upload(joints, {});
        const SkinningPass::Pose pose{
            pass.jointBuffer().handle(), 0, uint32_t(joints.size()), VK_NULL_HANDLE, 0, 0};
        const std::vector<MeshVertex> gpu = deformOnDevice(pass, mesh, pose, target);

        content::deformPrimitive(primitive, skin.jointMatrices, {}, cpu);
        for (size_t v = 0; v < gpu.size(); ++v) {
            worstPosition =
                std::max(worstPosition, distance3(gpu[v].position, cpu.positions[v].data()));
            worstNormal = std::max(worstNormal, distance3(gpu[v].normal, cpu.normals[v].data()));
            largestMotion =
                std::max(largestMotion, distance3(gpu[v].position, primitive.positions[v].data()));
            // Attributes the pass does not deform are copied.
            ASSERT_EQ(gpu[v].uv0[0], primitive.uv0[v][0]);
            ASSERT_EQ(gpu[v].uv0[1], primitive.uv0[v][1]);
        }
    }
    std::printf(
        "Fox Walk, 10 times, %u vertices: largest |GPU - CPU| position %.3g units, "
        "normal %.3g; largest move from the bind pose %.3g\n",
        mesh.vertexCount, double(worstPosition), double(worstNormal), double(largestMotion));
    EXPECT_LT(worstPosition, 1e-4f);
    EXPECT_LT(worstNormal, 1e-4f);
    EXPECT_GT(largestMotion, 1.0f);  // the clip really moved the mesh
    EXPECT_EQ(test::sharedContext().validationMessages(), 0u);
}

// Morph targets and tangents on the device against the CPU: a synthetic triangle with two
// targets (position, normal and tangent deltas) at fractional weights, and one joint turning
// it a quarter turn (the tangent must turn with it).
TEST(GpuSkinning, MorphTargetsAndTangentsMatchTheCpuReference) {
    content::Model model;
    content::Primitive p;
    p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    p.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    p.tangents = {{1, 0, 0, 1}, {1, 0, 0, -1}, {1, 0, 0, 1}};
    p.uv0 = {{0, 0}, {1, 0}, {0, 1}};
    p.indices = {0, 1, 2};
    p.joints = {{0, 1, 0, 0}, {0, 1, 0, 0}, {1, 0, 0, 0}};
    p.weights = {{0.25f, 0.75f, 0, 0}, {1, 0, 0, 0}, {1, 0, 0, 0}};
    content::MorphTarget a, b;
    a.positionDeltas = {{0, 0, 1}, {0, 0.5f, 0}, {0.25f, 0, 0}};
    a.normalDeltas = {{0.5f, 0, 0}, {0, 0, 0}, {0, 0.5f, 0}};
    a.tangentDeltas = {{0, 0.5f, 0}, {0, 0, 0.5f}, {0, 0, 0}};
    b.positionDeltas = {{1, 1, 0}, {0, 0, -1}, {0, 0, 0}};
    p.morphTargets = {a, b};
    content::Mesh mesh;
    mesh.primitives.push_back(p);
    model.meshes.push_back(mesh);

    SceneResources resources(test::sharedContext());
    const uint32_t meshId = resources.addModel(model).firstPrimitiveOfMesh[0];
    ASSERT_TRUE(resources.mesh(meshId).deformable());
    ASSERT_EQ(resources.mesh(meshId).morphTargetCount, 2u);
    resources.deformedVertexBuffers(7, meshId, false);
    SkinningPass pass(test::sharedContext());

    ecs::Mat4 quarterTurn{};  // about +Z, then moved by (2, 0, 0)
    const float m[16] = {0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 2, 0, 0, 1};
    std::memcpy(quarterTurn.m, m, sizeof(m));
    const std::vector<ecs::Mat4> jointMatrices = {ecs::Mat4{}, quarterTurn};
    const std::vector<float> weights = {0.3f, 0.6f};
    std::vector<glm::mat4> joints(2);
    for (size_t j = 0; j < 2; ++j)
        std::memcpy(&joints[j][0][0], jointMatrices[j].m, sizeof(glm::mat4));
    pass.upload(joints, weights);
    const SkinningPass::Pose pose{pass.jointBuffer().handle(),       0, 2,
                                  pass.morphWeightBuffer().handle(), 0, 2};
    const std::vector<MeshVertex> gpu =
        deformOnDevice(pass, resources.mesh(meshId), pose, *resources.deformedBuffer(7));

    content::DeformedVertices cpu;
    content::deformPrimitive(p, jointMatrices, weights, cpu);
    ASSERT_EQ(cpu.tangents.size(), 3u);
    for (size_t v = 0; v < 3; ++v) {
        EXPECT_LT(distance3(gpu[v].position, cpu.positions[v].data()), 1e-6f) << "vertex " << v;
        EXPECT_LT(distance3(gpu[v].normal, cpu.normals[v].data()), 1e-6f) << "vertex " << v;
        EXPECT_LT(distance3(gpu[v].tangent, cpu.tangents[v].data()), 1e-6f) << "vertex " << v;
        EXPECT_EQ(gpu[v].tangent[3], p.tangents[v][3]) << "vertex " << v;
    }
    // Vertex 2 rides joint 1 alone: its tangent (1, 0, 0) turns to (0, 1, 0).
    EXPECT_NEAR(gpu[2].tangent[1], 1.0f, 1e-6f);
    EXPECT_EQ(test::sharedContext().validationMessages(), 0u);
}
