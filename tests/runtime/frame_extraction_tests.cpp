// The light table's slot order (issue 41), and frame extraction of animated meshes (issue 24's
// motion vectors): a skinned instance's draw names this frame's deformed vertices and last
// frame's, in two buffers that swap each frame; its first frame, and a frame after one it was
// not drawn in, name the same buffer for both.
#include <gtest/gtest.h>

#include <vector>

#include "candela/content/components/animation.h"
#include "candela/content/components/light.h"
#include "candela/content/components/mesh_instance.h"
#include "candela/content/procedural_mesh.h"
#include "candela/ecs/transform.h"
#include "candela/render/gpu_context.h"
#include "candela/runtime/frame_extraction.h"
#include "candela/runtime/light_table.h"

using namespace candela;
using namespace candela::runtime;

TEST(FrameExtraction, SkinnedDrawsNameLastFramesDeformedVerticesForMotionVectors) {
    render::GpuContextOptions options;
    options.validation = render::ValidationMode::Required;
    render::GpuContext context(options);
    render::SceneResources resources(context);

    // A box bound to one joint.
    content::Model model;
    content::Primitive box = content::makeBox({0.5f, 0.5f, 0.5f});
    box.joints.assign(box.positions.size(), {0, 0, 0, 0});
    box.weights.assign(box.positions.size(), {1.0f, 0.0f, 0.0f, 0.0f});
    model.materials.emplace_back();
    box.material = 0;
    model.meshes.emplace_back().primitives.push_back(std::move(box));

    ecs::Registry registry;
    LightTable lights(registry);
    const ecs::Entity e = registry.create();
    registry.emplace<ecs::WorldTransform>(e);
    registry.emplace<content::MeshInstance>(e, content::MeshInstance{&model, 0});
    content::Skin skin;
    skin.jointMatrices.resize(1);
    registry.emplace<content::Skin>(e, skin);

    ExtractedFrame frame;
    auto extract = [&](float jointX) {
        registry.get<content::Skin>(e).jointMatrices[0].m[12] = jointX;
        extractFrame(registry, lights, resources, 1.0f, frame);
        EXPECT_EQ(frame.draws.size(), 1u);
        return frame.draws.empty() ? render::DrawItem{} : frame.draws[0];
    };
    const render::DrawItem first = extract(0.0f);
    ASSERT_NE(first.deformedVertices, VK_NULL_HANDLE);
    EXPECT_EQ(first.previousDeformedVertices, first.deformedVertices) << "no last frame yet";
    const render::DrawItem second = extract(0.1f);
    EXPECT_NE(second.deformedVertices, first.deformedVertices);
    EXPECT_EQ(second.previousDeformedVertices, first.deformedVertices);
    const render::DrawItem third = extract(0.2f);
    EXPECT_EQ(third.deformedVertices, first.deformedVertices) << "the two buffers swap";
    EXPECT_EQ(third.previousDeformedVertices, second.deformedVertices);

    // Not drawn for a frame: the next one has no deformation motion.
    registry.remove<content::MeshInstance>(e);
    extractFrame(registry, lights, resources, 1.0f, frame);
    EXPECT_TRUE(frame.draws.empty());
    registry.emplace<content::MeshInstance>(e, content::MeshInstance{&model, 0});
    const render::DrawItem back = extract(0.3f);
    EXPECT_EQ(back.previousDeformedVertices, back.deformedVertices);
}

// Issue 19: a mesh's wires (content::Mesh::wires) go to the frame's wire list with the
// instance's world matrix and their material, never to the mesh draws.
TEST(FrameExtraction, WiresOfAMeshInstanceBecomeWireDraws) {
    render::GpuContextOptions options;
    options.validation = render::ValidationMode::Required;
    render::GpuContext context(options);
    render::SceneResources resources(context);

    content::Model model;
    content::Material cable;
    cable.wireRadius = 0.01f;
    model.materials.push_back(cable);
    content::Wire wire;
    wire.positions = {{0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}};
    wire.segments = {0, 1};
    wire.radius = cable.wireRadius;
    wire.material = 0;
    content::Mesh& mesh = model.meshes.emplace_back();
    mesh.primitives.push_back(content::makeBox({0.5f, 0.5f, 0.5f}));
    mesh.wires.push_back(wire);

    ecs::Registry registry;
    LightTable lights(registry);
    const ecs::Entity e = registry.create();
    ecs::WorldTransform world;
    world.matrix.m[13] = 7.0f;  // y
    registry.emplace<ecs::WorldTransform>(e, world);
    registry.emplace<content::MeshInstance>(e, content::MeshInstance{&model, 0});

    ExtractedFrame frame;
    extractFrame(registry, lights, resources, 1.0f, frame);
    EXPECT_EQ(frame.draws.size(), 1u) << "the box only";
    ASSERT_EQ(frame.wires.size(), 1u);
    EXPECT_EQ(frame.wires[0].wire, &model.meshes[0].wires[0]);
    EXPECT_EQ(frame.wires[0].material, &model.materials[0]);
    EXPECT_FLOAT_EQ(frame.wires[0].world[3][1], 7.0f);
}

// Issue 41: the slot groups follow the lighting shader's loops by class (light_loops.h):
// plain points, spheres and tubes, rects and disks, then the casters, casting rects and disks
// last; each group keeps the registry's order.
TEST(LightTableOrder, GroupsFollowTheLightingLoops) {
    ecs::Registry registry;
    LightTable table(registry);
    auto add = [&](content::LightType type, float radius, bool casts, float lumens) {
        const ecs::Entity e = registry.create();
        registry.emplace<ecs::WorldTransform>(e);
        content::Light light;
        light.type = type;
        light.sourceRadius = radius;
        light.castShadows = casts;
        light.lumens = lumens;
        registry.emplace<content::Light>(e, light);
    };
    add(content::LightType::Rect, 0.0f, true, 1.0f);    // group 4
    add(content::LightType::Point, 0.1f, true, 2.0f);   // group 3
    add(content::LightType::Disk, 0.2f, false, 3.0f);   // group 2
    add(content::LightType::Point, 0.1f, false, 4.0f);  // group 1
    add(content::LightType::Spot, 0.0f, false, 5.0f);   // group 0
    add(content::LightType::Rect, 0.0f, false, 6.0f);   // group 2
    add(content::LightType::Point, 0.0f, false, 7.0f);  // group 0
    table.update();
    std::vector<float> order;
    for (const render::LightInstance& l : table.lights())
        order.push_back(l.light.lumens);
    EXPECT_EQ(order, (std::vector<float>{5.0f, 7.0f, 4.0f, 3.0f, 6.0f, 2.0f, 1.0f}));
}

// Issue 41: plain points first, then lights with a size, then lights that cast shadows take
// the last slots (cluster lists follow that order, and the lighting pass walks each group
// without the others' code); a light that starts casting moves with a rebuild, an edit that
// keeps its group rewrites its slot.
TEST(LightTableOrder, CastersTakeTheLastSlots) {
    ecs::Registry registry;
    LightTable table(registry);
    std::vector<ecs::Entity> entities;
    for (int i = 0; i < 5; ++i) {
        const ecs::Entity e = registry.create();
        registry.emplace<ecs::WorldTransform>(e);
        content::Light light;
        light.castShadows = i % 2 == 0 && i < 4;    // lights 0 and 2 cast
        light.sourceRadius = i == 4 ? 0.1f : 0.0f;  // light 4 is a sphere
        light.lumens = 100.0f * float(i + 1);
        registry.emplace<content::Light>(e, light);
        entities.push_back(e);
    }
    table.update();
    ASSERT_EQ(table.lights().size(), 5u);
    auto casters = [&] {
        std::vector<bool> cast;
        for (const render::LightInstance& l : table.lights())
            cast.push_back(l.light.castShadows);
        return cast;
    };
    EXPECT_EQ(casters(), (std::vector<bool>{false, false, false, true, true}));
    EXPECT_EQ(table.lights()[2].light.sourceRadius, 0.1f);  // after the plain points

    registry.patch<content::Light>(entities[1], [](content::Light& l) { l.lumens = 5.0f; });
    table.update();
    EXPECT_FALSE(table.restructured());
    EXPECT_EQ(table.changedSlots().size(), 1u);

    registry.patch<content::Light>(entities[3], [](content::Light& l) { l.castShadows = true; });
    table.update();
    EXPECT_TRUE(table.restructured());
    EXPECT_EQ(casters(), (std::vector<bool>{false, false, true, true, true}));
}
