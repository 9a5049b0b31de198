#include "demo_scene.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <numbers>

#include "candela/content/components/camera.h"
#include "candela/content/components/light.h"
#include "candela/content/components/mesh_instance.h"
#include "candela/content/components/name.h"
#include "candela/content/model_instantiation.h"
#include "candela/content/procedural_mesh.h"
#include "candela/ecs/hierarchy.h"
#include "candela/ecs/transform.h"

namespace candela::runtime {

namespace {

// A light that circles `center` at `radius` metres, `speed` radians per second.
struct OrbitingLight {
    ecs::Vec3 center;
    float radius;
    float speed;
    float phase;
};

std::filesystem::path sharedAssets() {
    if (const char* dir = std::getenv("CANDELA_ASSETS")) return dir;
    return CANDELA_SHARED_ASSETS;
}

content::Material material(std::array<float, 3> color, float metallic, float roughness) {
    content::Material m;
    m.baseColorFactor = {color[0], color[1], color[2], 1.0f};
    m.metallicFactor = metallic;
    m.roughnessFactor = roughness;
    return m;
}

// One model holding every procedural mesh of the demo, one mesh per (shape, material).
struct DemoMeshes {
    content::Model model;
    int32_t add(content::Primitive primitive, const content::Material& m) {
        primitive.material = int32_t(model.materials.size());
        model.materials.push_back(m);
        content::Mesh mesh;
        mesh.primitives.push_back(std::move(primitive));
        model.meshes.push_back(std::move(mesh));
        return int32_t(model.meshes.size() - 1);
    }
};

ecs::Entity place(ecs::Registry& registry, const std::string& name, ecs::Vec3 position,
                  ecs::Quat rotation = {}, ecs::Vec3 scale = {1.0f, 1.0f, 1.0f}) {
    ecs::Entity e = registry.create();
    registry.emplace<content::Name>(e, content::Name{name});
    registry.emplace<ecs::LocalTransform>(e, ecs::LocalTransform{position, rotation, scale});
    registry.emplace<ecs::WorldTransform>(e);
    return e;
}

content::Light pointLight(std::array<float, 3> color, float lumens, float radius) {
    content::Light l;
    l.color = color;
    l.lumens = lumens;
    l.attenuationRadius = radius;
    return l;
}

}  // namespace

void buildDemoScene(SceneWorld& world, content::Diagnostics& diagnostics) {
    ecs::Registry& registry = world.registry;
    auto meshes = std::make_unique<DemoMeshes>();
    const int32_t floor =
        meshes->add(content::makePlane(8.0f, 8), material({0.5f, 0.5f, 0.52f}, 0.0f, 0.6f));
    const int32_t wall = meshes->add(content::makeBox({8.0f, 2.5f, 0.2f}),
                                     material({0.7f, 0.66f, 0.6f}, 0.0f, 0.9f));
    const int32_t pillar = meshes->add(content::makeBox({0.25f, 2.0f, 0.25f}),
                                       material({0.8f, 0.78f, 0.74f}, 0.0f, 0.5f));
    std::vector<int32_t> spheres;
    for (int i = 0; i < 5; ++i) {
        float roughness = 0.1f + 0.2f * float(i);
        spheres.push_back(meshes->add(content::makeSphere(0.3f),
                                      material({1.0f, 0.77f, 0.34f}, 1.0f, roughness)));
        spheres.push_back(
            meshes->add(content::makeSphere(0.3f), material({0.8f, 0.1f, 0.1f}, 0.0f, roughness)));
    }
    content::Material translucent = material({0.9f, 0.85f, 0.8f}, 0.0f, 0.5f);
    translucent.shadingModel = content::ShadingModel::Subsurface;
    translucent.subsurfaceColor = {1.0f, 0.3f, 0.15f};
    translucent.subsurfaceOpacity = 0.2f;
    const int32_t leaf = meshes->add(content::makeBox({0.6f, 0.8f, 0.02f}), translucent);
    content::Material toon = material({0.0f, 0.0f, 0.0f}, 0.0f, 0.35f);
    toon.shadingModel = content::ShadingModel::Legacy;
    toon.diffuseColor = {0.15f, 0.45f, 0.9f};
    toon.specularColor = {0.6f, 0.6f, 0.6f};
    const int32_t toonSphere = meshes->add(content::makeSphere(0.45f), toon);
    content::Material neon = material({0.0f, 0.0f, 0.0f}, 0.0f, 1.0f);
    neon.shadingModel = content::ShadingModel::Unlit;
    neon.emissiveFactor = {40.0f, 4.0f, 30.0f};
    const int32_t neonTube = meshes->add(content::makeBox({0.6f, 0.03f, 0.03f}), neon);

    const content::Model& model = world.adoptModel(
        std::unique_ptr<content::Model>(new content::Model(std::move(meshes->model))));
    auto draw = [&](ecs::Entity e, int32_t mesh) {
        registry.emplace<content::MeshInstance>(e, content::MeshInstance{&model, mesh});
    };

    draw(place(registry, "floor", {0.0f, 0.0f, 0.0f}), floor);
    draw(place(registry, "back wall", {0.0f, 2.5f, -4.0f}), wall);
    for (int i = 0; i < 4; ++i) {
        draw(place(registry, "pillar", {-4.5f + 3.0f * float(i), 2.0f, -2.8f}), pillar);
    }
    for (size_t i = 0; i < spheres.size(); ++i) {
        float x = -2.4f + 1.2f * float(i / 2);
        float z = i % 2 ? 2.2f : 1.4f;
        draw(place(registry, "sphere", {x, 0.3f, z}), spheres[i]);
    }
    draw(place(registry, "translucent panel", {2.9f, 0.8f, -0.6f},
               ecs::Quat::fromAxisAngle({0.0f, 1.0f, 0.0f}, -0.5f)),
         leaf);
    draw(place(registry, "toon sphere", {-3.2f, 0.45f, -0.4f}), toonSphere);

    const std::filesystem::path helmet = sharedAssets() / "models/DamagedHelmet/DamagedHelmet.glb";
    // The helmet stands on an invisible plinth in the middle of the room.
    ecs::Entity plinth =
        place(registry, "helmet plinth", {0.0f, 1.1f, -0.6f},
              ecs::Quat::fromAxisAngle({0.0f, 1.0f, 0.0f}, 0.35f), {0.9f, 0.9f, 0.9f});
    world.loadGltf(helmet, diagnostics, plinth);

    // Coloured point lights circling the room, a warm lamp bulb (sphere light) and a neon tube.
    const std::array<std::array<float, 3>, 6> colors = {{{1.0f, 0.3f, 0.2f},
                                                         {0.2f, 1.0f, 0.4f},
                                                         {0.3f, 0.4f, 1.0f},
                                                         {1.0f, 0.8f, 0.2f},
                                                         {0.9f, 0.3f, 1.0f},
                                                         {0.2f, 0.9f, 1.0f}}};
    for (int i = 0; i < 48; ++i) {
        float t = float(i) / 48.0f;
        ecs::Entity e = place(registry, "orbiting light", {});
        registry.emplace<content::Light>(e, pointLight(colors[i % colors.size()], 250.0f, 3.5f));
        registry.emplace<OrbitingLight>(
            e, OrbitingLight{{0.0f, 0.25f + 1.5f * float(i % 4) / 3.0f, 0.0f},
                             1.5f + 3.5f * t,
                             0.4f + 0.5f * float(i % 3) / 2.0f,
                             t * 2.0f * std::numbers::pi_v<float> * 5.0f});
    }
    content::Light bulb = pointLight({1.0f, 0.78f, 0.55f}, 1600.0f, 9.0f);
    bulb.sourceRadius = 0.08f;
    registry.emplace<content::Light>(place(registry, "lamp bulb", {-1.5f, 2.6f, 0.8f}), bulb);
    content::Light tube = pointLight({1.0f, 0.1f, 0.75f}, 1200.0f, 6.0f);
    tube.sourceLength = 1.2f;
    tube.sourceRadius = 0.03f;
    ecs::Entity neonEntity = place(registry, "neon tube", {1.8f, 2.2f, -3.7f});
    registry.emplace<content::Light>(neonEntity, tube);
    draw(neonEntity, neonTube);
    // Back-light for the translucent panel: the subsurface model shows light through it.
    registry.emplace<content::Light>(place(registry, "panel backlight", {3.6f, 1.0f, -1.5f}),
                                     pointLight({1.0f, 0.9f, 0.7f}, 900.0f, 4.0f));

    content::Camera camera;
    camera.exposureMode = content::ExposureMode::Manual;
    camera.manualEv100 = 4.5f;
    camera.verticalFov = 0.95f;
    ecs::Entity cam = place(registry, "camera", {0.0f, 2.0f, 6.2f},
                            ecs::Quat::fromAxisAngle({1.0f, 0.0f, 0.0f}, -0.2f));
    registry.emplace<content::Camera>(cam, camera);
    animateDemoScene(world, 0.0);
}

void animateDemoScene(SceneWorld& world, double seconds) {
    world.registry.view<ecs::LocalTransform, const OrbitingLight>().each(
        [&](ecs::Entity e, ecs::LocalTransform& local, const OrbitingLight& orbit) {
            float angle = orbit.phase + orbit.speed * float(seconds);
            local.position = orbit.center + ecs::Vec3{std::cos(angle) * orbit.radius, 0.0f,
                                                      std::sin(angle) * orbit.radius};
            world.registry.markChanged<ecs::LocalTransform>(e);
        });
    world.updateTransforms();
}

}  // namespace candela::runtime
