#include "demo_scene.h"
#include "demo_screen_image.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <numbers>

#include "candela/content/components/animation.h"
#include "candela/content/components/atmosphere.h"
#include "candela/content/components/camera.h"
#include "candela/content/components/collider.h"
#include "candela/content/components/fog.h"
#include "candela/content/components/hair_growth.h"
#include "candela/content/components/light.h"
#include "candela/content/components/mesh_instance.h"
#include "candela/content/components/name.h"
#include "candela/content/components/rigid_body.h"
#include "candela/content/diagnostics.h"
#include "candela/content/light_texture.h"
#include "candela/content/procedural_mesh.h"
#include "candela/ecs/hierarchy.h"
#include "candela/ecs/transform.h"
#include "candela/runtime/application.h"
#include "candela/runtime/fly_camera.h"

namespace candela::runtime {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// A light that drifts on a Lissajous figure inside a box: x, y, z each oscillate.
// The fox walking down the hall (issue 20): its root entity, how far it has gone.
struct DemoFox {
    float distance = 0;
};
constexpr float kFoxStartZ = -6.5f;
constexpr float kFoxPathLength = 12.0f;  // then it starts again at the far end
constexpr float kFoxGaitSeconds = 4.0f;  // walk, then run, then walk...

struct DriftingLight {
    ecs::Vec3 center;
    ecs::Vec3 amplitude;
    ecs::Vec3 frequency;  // radians per second per axis
    ecs::Vec3 phase;
};

// Marks the demo camera; `flying` once the user took over in a window.
struct DemoCamera {
    bool flying = false;
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

content::Material emissive(std::array<float, 3> radiance) {
    content::Material m = material({0.0f, 0.0f, 0.0f}, 0.0f, 1.0f);
    m.shadingModel = content::ShadingModel::Unlit;
    m.emissiveFactor = radiance;
    return m;
}

content::Material toon(std::array<float, 3> diffuse) {
    content::Material m = material({0.0f, 0.0f, 0.0f}, 0.0f, 0.3f);
    m.shadingModel = content::ShadingModel::Legacy;
    m.diffuseColor = diffuse;
    m.specularColor = {0.7f, 0.7f, 0.7f};
    return m;
}

content::Material subsurface(std::array<float, 3> color, std::array<float, 3> scatter) {
    content::Material m = material(color, 0.0f, 0.45f);
    m.shadingModel = content::ShadingModel::Subsurface;
    m.subsurfaceColor = scatter;
    m.subsurfaceOpacity = 0.15f;
    return m;
}

// One model holding every procedural mesh of the demo, one mesh per (shape, material).
// A 64x64 rust mask (red channel; tiles): blotches from two octaves of sines, soft-edged.
content::Rgba8Image rustMask() {
    content::Rgba8Image image;
    image.width = image.height = 64;
    image.rgba.resize(64 * 64 * 4);
    for (uint32_t y = 0; y < 64; ++y) {
        for (uint32_t x = 0; x < 64; ++x) {
            const float u = 6.2831853f * float(x) / 64.0f, v = 6.2831853f * float(y) / 64.0f;
            const float n = std::sin(2.0f * u + std::sin(3.0f * v)) * std::cos(3.0f * v) +
                            0.5f * std::sin(5.0f * u - 4.0f * v + 1.3f);
            const float rust = std::clamp((n - 0.35f) / 0.3f, 0.0f, 1.0f);
            uint8_t* texel = &image.rgba[(size_t(y) * 64 + x) * 4];
            texel[0] = uint8_t(std::lround(rust * 255.0f));
            texel[1] = texel[2] = 0;
            texel[3] = 255;
        }
    }
    return image;
}

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

// Saturated colours around the hue circle, hue in [0, 1).
std::array<float, 3> hueColor(float hue) {
    std::array<float, 3> c;
    for (int i = 0; i < 3; ++i) {
        float h = std::fmod(hue + float(i) / 3.0f, 1.0f);
        c[size_t(i)] = std::clamp(std::fabs(h * 6.0f - 3.0f) - 1.0f, 0.0f, 1.0f);
    }
    return {std::max(c[0], 0.05f), std::max(c[1], 0.05f), std::max(c[2], 0.05f)};
}

// Deterministic pseudo-random numbers in [0, 1) (the level is the same on every machine).
float hash01(uint32_t n) {
    n = (n ^ 61u) ^ (n >> 16);
    n *= 9u;
    n ^= n >> 4;
    n *= 0x27d4eb2du;
    n ^= n >> 15;
    return float(n & 0xffffffu) / float(0x1000000u);
}

// Hall: x in [-6.5, 6.5], z in [-9.5, 8], colonnades at x = +-4, open roof between ribs.
constexpr float kColonnadeX = 4.0f;
constexpr float kPillarHeight = 4.4f;
constexpr int kPillarsPerRow = 6;
constexpr float kFirstPillarZ = -8.0f;
constexpr float kPillarSpacing = 2.8f;
// Volumetric scales (content::Light::volumetric) of the lights the dust should show.
constexpr float kDustGlow = 6.0f;
// The sun scatters in the dust as every other light does (scale 1): the dust fills only the
// hall (its Fog's bounds), so the sun's in-scattering cannot haze the meadow outside.
constexpr float kDustSunShafts = 1.0f;
constexpr float kDustAreaLights = 0.15f;
// The hall's walls end at y = kWallTop; the roof lies on them, open in slits over the nave
// (skylights) between the ribs, and the side walls have windows between the pillars: the
// sun's shafts through the dust (issue 17) come through both.
constexpr float kWallTop = 5.2f;
constexpr float kRoofHalfThickness = 0.1f;
constexpr float kSkylightWidth = 0.8f;  // along z
constexpr float kWindowWidth = 1.2f;    // along z
constexpr float kWindowBottom = 3.4f, kWindowTop = 4.6f;
constexpr float kHallBackZ = -10.0f, kHallFrontZ = 8.0f;
constexpr float kDoorHalfWidth = 2.0f, kDoorHeight = 3.6f;
// The power lines (issue 19) cross the meadow in front of the hall, against the sky.
constexpr float kPowerLineZ = 22.0f;

}  // namespace

// Issue 46: three crates dropped askew onto one another (they tumble into a heap), a rubber
// ball that bounces off them and a steel ball that rolls across the floor, with the floor as
// their static collider. They come to rest in a few seconds and then sleep (no cost).
template <class Draw>
void addDemoProps(ecs::Registry& registry, Draw&& draw, int32_t crate, int32_t rubberBall,
                  int32_t steelBall) {
    content::Collider ground;
    ground.halfExtents = ecs::Vec3{6.5f, 0.5f, 9.0f};
    registry.emplace<content::Collider>(place(registry, "floor collider", {0.0f, -0.5f, -1.0f}),
                                        ground);
    content::RigidBody wood;
    wood.mass = 8.0f;
    wood.friction = 0.7f;
    for (int i = 0; i < 3; ++i) {
        const ecs::Entity e =
            draw(place(registry, "crate", {2.6f + 0.12f * float(i), 0.4f + 0.7f * float(i), 4.6f},
                       ecs::Quat::fromAxisAngle({0.3f, 1.0f, 0.2f}, 0.5f * float(i))),
                 crate);
        content::Collider box;
        box.halfExtents = ecs::Vec3{0.25f, 0.25f, 0.25f};
        registry.emplace<content::Collider>(e, box);
        registry.emplace<content::RigidBody>(e, wood);
    }
    content::Collider ball;
    ball.shape = content::ColliderShape::Sphere;
    content::RigidBody rubber;
    rubber.mass = 0.4f;
    rubber.restitution = 0.75f;
    ball.radius = 0.18f;
    const ecs::Entity bouncy = draw(place(registry, "rubber ball", {2.9f, 3.2f, 4.7f}), rubberBall);
    registry.emplace<content::Collider>(bouncy, ball);
    registry.emplace<content::RigidBody>(bouncy, rubber);
    content::RigidBody steel;
    steel.mass = 7.0f;
    steel.restitution = 0.1f;
    steel.linearVelocity = {-1.2f, 0.0f, 0.4f};
    ball.radius = 0.15f;
    const ecs::Entity rolling = draw(place(registry, "steel ball", {3.6f, 0.15f, 5.6f}), steelBall);
    registry.emplace<content::Collider>(rolling, ball);
    registry.emplace<content::RigidBody>(rolling, steel);
}

const CameraPath& demoCameraPath() {
    // A tour: in through the door, the toon figures, the helmet, the sphere grid and neon, the
    // back-lit panels, a high view back over the hall, then out of the door into the daylight
    // (auto exposure adapts: issue 24) and a look up at the power lines across the sky.
    static const CameraPath path(
        {
            {{0.0f, 2.2f, 9.0f}, {0.0f, 1.6f, -3.0f}},
            {{-3.0f, 1.5f, 3.2f}, {-2.3f, 1.0f, 0.0f}},
            {{-1.4f, 1.9f, -0.6f}, {0.0f, 1.5f, -3.0f}},
            {{1.6f, 2.8f, -5.0f}, {0.0f, 3.0f, -9.2f}},
            {{3.6f, 1.5f, 3.4f}, {2.2f, 1.0f, -0.3f}},
            {{1.5f, 3.0f, 5.0f}, {-1.0f, 1.0f, -4.0f}},
            {{0.3f, 1.7f, 11.5f}, {0.0f, 4.5f, 30.0f}},
            {{3.0f, 1.7f, 15.0f}, {-8.0f, 7.0f, kPowerLineZ}},
        },
        4.0f);
    return path;
}

float demoTimeOfDay(double seconds) {
    const double loop = double(demoCameraPath().loopSeconds());
    return kDemoDayStartHours + kDemoDayHoursPerSecond * float(std::fmod(seconds, loop));
}

void buildDemoScene(SceneWorld& world, content::Diagnostics& diagnostics) {
    ecs::Registry& registry = world.registry;

    // The sphere grid goes in first: its bounds (alone in the world) size its placement.
    const std::filesystem::path grid =
        sharedAssets() / "models/MetalRoughSpheresNoTextures/MetalRoughSpheresNoTextures.glb";
    ecs::Entity gridRoot = place(registry, "sphere grid", {});
    if (world.loadGltf(grid, diagnostics, gridRoot)) {
        SceneBounds b = world.bounds();
        if (!b.empty) {
            // Stand the grid's larger side up to 3 m wide against the back wall, centred.
            float width = std::max(b.max[0] - b.min[0], 1e-6f);
            float scale = 3.0f / width;
            ecs::Vec3 center = {0.5f * (b.min[0] + b.max[0]), 0.5f * (b.min[1] + b.max[1]),
                                b.max[2]};
            auto& local = registry.get<ecs::LocalTransform>(gridRoot);
            local.scale = {scale, scale, scale};
            local.position = ecs::Vec3{0.0f, 3.0f, -9.0f} - center * scale;
            registry.markChanged<ecs::LocalTransform>(gridRoot);
        }
    }

    auto meshes = std::make_unique<DemoMeshes>();
    // Polished stone (issue 18): glossy enough for screen-space reflections of the neon tubes
    // and the columns, which the demo asks for as a scene file's "ssr": "hiz" would.
    const int32_t floor =
        meshes->add(content::makePlane(12.0f, 12), material({0.16f, 0.15f, 0.14f}, 0.0f, 0.15f));
    world.sceneSettings().ssr = content::SsrMode::Hiz;
    const int32_t runner = meshes->add(content::makeBox({1.0f, 0.01f, 8.0f}),
                                       material({0.75f, 0.75f, 0.78f}, 1.0f, 0.12f));
    const content::Material stone = material({0.72f, 0.68f, 0.62f}, 0.0f, 0.8f);
    const int32_t pillar = meshes->add(content::makeBox({0.28f, kPillarHeight * 0.5f, 0.28f}),
                                       material({0.8f, 0.78f, 0.74f}, 0.0f, 0.45f));
    const int32_t plinthBlock = meshes->add(content::makeBox({0.45f, 0.12f, 0.45f}), stone);
    const int32_t architrave = meshes->add(content::makeBox({0.45f, 0.25f, 8.6f}), stone);
    const int32_t rib = meshes->add(content::makeBox({4.45f, 0.12f, 0.15f}),
                                    material({0.35f, 0.22f, 0.12f}, 0.0f, 0.7f));
    const int32_t backWall = meshes->add(content::makeBox({6.5f, 3.2f, 0.25f}),
                                         material({0.45f, 0.12f, 0.1f}, 0.0f, 0.9f));
    // Side walls in pieces around their windows: below, above, and the piers between.
    const float hallHalfLength = 0.5f * (kHallFrontZ - kHallBackZ);
    const int32_t sideWallBelow =
        meshes->add(content::makeBox({0.25f, 0.5f * kWindowBottom, hallHalfLength}), stone);
    const int32_t sideWallAbove = meshes->add(
        content::makeBox({0.25f, 0.5f * (kWallTop - kWindowTop), hallHalfLength}), stone);
    const float pierHalfHeight = 0.5f * (kWindowTop - kWindowBottom);
    const int32_t innerPier = meshes->add(
        content::makeBox({0.25f, pierHalfHeight, 0.5f * (kPillarSpacing - kWindowWidth)}), stone);
    const float endPierLength = kFirstPillarZ + 0.5f * kPillarSpacing - 0.5f * kWindowWidth -
                                kHallBackZ;  // the back wall to the first window
    const int32_t endPier =
        meshes->add(content::makeBox({0.25f, pierHalfHeight, 0.5f * endPierLength}), stone);
    // The front wall, with a door 4 m wide, and the roof in panels between the skylights.
    const float frontPieceHalfWidth = 0.5f * (7.0f - kDoorHalfWidth);
    const int32_t frontWall =
        meshes->add(content::makeBox({frontPieceHalfWidth, 0.5f * kWallTop, 0.125f}), stone);
    const int32_t lintel = meshes->add(
        content::makeBox({kDoorHalfWidth, 0.5f * (kWallTop - kDoorHeight), 0.125f}), stone);
    const content::Material roofTiles = material({0.3f, 0.2f, 0.16f}, 0.0f, 0.85f);
    const int32_t roofPanel = meshes->add(
        content::makeBox({7.0f, kRoofHalfThickness, 0.5f * (kPillarSpacing - kSkylightWidth)}),
        roofTiles);
    const float endRoofLength =
        kFirstPillarZ + 0.5f * kPillarSpacing - 0.5f * kSkylightWidth - kHallBackZ;
    const int32_t endRoofPanel =
        meshes->add(content::makeBox({7.0f, kRoofHalfThickness, 0.5f * endRoofLength}), roofTiles);
    // The meadow around the hall, under the floor (which reaches 3 m past the door).
    const int32_t meadow =
        meshes->add(content::makePlane(80.0f, 8), material({0.12f, 0.22f, 0.06f}, 0.0f, 0.9f));
    const int32_t pedestal = meshes->add(content::makeBox({0.5f, 0.5f, 0.5f}),
                                         material({0.9f, 0.9f, 0.88f}, 0.0f, 0.25f));
    const int32_t gold = meshes->add(content::makeBox({0.55f, 0.04f, 0.55f}),
                                     material({1.0f, 0.77f, 0.34f}, 1.0f, 0.3f));
    std::vector<int32_t> spheres;
    for (int i = 0; i < 6; ++i) {
        float roughness = 0.05f + 0.18f * float(i);
        spheres.push_back(meshes->add(content::makeSphere(0.28f),
                                      material({0.95f, 0.64f, 0.54f}, 1.0f, roughness)));
        spheres.push_back(
            meshes->add(content::makeSphere(0.28f), material({0.1f, 0.3f, 0.8f}, 0.0f, roughness)));
    }
    const int32_t panelAmber = meshes->add(content::makeBox({0.35f, 0.6f, 0.015f}),
                                           subsurface({0.9f, 0.75f, 0.5f}, {1.0f, 0.35f, 0.05f}));
    const int32_t panelJade = meshes->add(content::makeBox({0.35f, 0.6f, 0.015f}),
                                          subsurface({0.6f, 0.85f, 0.6f}, {0.1f, 0.9f, 0.3f}));
    const int32_t waxSphere = meshes->add(content::makeSphere(0.3f),
                                          subsurface({0.95f, 0.9f, 0.85f}, {1.0f, 0.25f, 0.2f}));
    const int32_t toonBody = meshes->add(content::makeSphere(0.42f), toon({0.95f, 0.95f, 1.0f}));
    const int32_t toonHead = meshes->add(content::makeSphere(0.28f), toon({0.95f, 0.95f, 1.0f}));
    const int32_t toonHat =
        meshes->add(content::makeBox({0.18f, 0.16f, 0.18f}), toon({0.1f, 0.1f, 0.12f}));
    const int32_t toonBall = meshes->add(content::makeSphere(0.3f), toon({0.15f, 0.45f, 0.9f}));
    const int32_t neonMagenta =
        meshes->add(content::makeBox({1.5f, 0.03f, 0.03f}), emissive({60.0f, 4.0f, 40.0f}));
    const int32_t neonCyan =
        meshes->add(content::makeBox({0.8f, 0.03f, 0.03f}), emissive({4.0f, 40.0f, 60.0f}));
    const int32_t bulbGlass =
        meshes->add(content::makeSphere(0.08f, 24, 12), emissive({2000.0f, 1500.0f, 900.0f}));
    const int32_t cord = meshes->add(content::makeBox({0.008f, 0.6f, 0.008f}),
                                     material({0.05f, 0.05f, 0.05f}, 0.0f, 0.6f));

    // Issue 21: brushed metal (KHR_materials_anisotropy, stretched along the sphere's
    // tangents, which run around it) and car paint (KHR_materials_clearcoat over a red base).
    content::Material brushedMetal = material({0.91f, 0.92f, 0.92f}, 1.0f, 0.3f);
    brushedMetal.anisotropyStrength = 0.8f;
    const int32_t brushedSphere = meshes->add(content::makeSphere(0.35f), brushedMetal);
    content::Material carPaint = material({0.5f, 0.02f, 0.03f}, 0.0f, 0.5f);
    carPaint.clearcoatFactor = 1.0f;
    carPaint.clearcoatRoughnessFactor = 0.03f;
    const int32_t paintSphere = meshes->add(content::makeSphere(0.35f), carPaint);
    // Issue 21: a layered material: rust over painted metal, blended by a procedural mask's
    // red channel, the rust's parameters at their own frequency (the mask at 3x the sphere's
    // UVs).
    content::Material rusty;
    content::MaterialLayer paint, rust;
    paint.name = "painted metal";
    paint.baseColorFactor = {0.05f, 0.25f, 0.12f, 1.0f};
    paint.roughnessFactor = 0.3f;
    rust.name = "rust";
    rust.baseColorFactor = {0.42f, 0.17f, 0.06f, 1.0f};
    rust.roughnessFactor = 0.9f;
    rust.specular = 0.3f;
    rusty.layering.layers = {paint, rust};
    rusty.layering.maskTexture.texture = int32_t(meshes->model.textures.size());
    rusty.layering.maskTexture.transform.scale = {3.0f, 3.0f};
    meshes->model.textures.push_back({"rust mask", int32_t(meshes->model.images.size()), {}});
    meshes->model.images.push_back(rustMask());
    const int32_t rustySphere = meshes->add(content::makeSphere(0.35f), rusty);

    // Issue 19 (Persson 2014, GPU Pro 5, "Wire Antialiasing"): power lines across the sky over the
    // meadow in front of the hall, seen from the door on the way out: three conductors sagging
    // between poles every 15 m outside the side walls, 2.4 cm thick: under a pixel wide from the
    // tour's viewpoints, drawn by the wire pass at their real energy instead of a pixel-wide line.
    const int32_t powerLines = int32_t(meshes->model.meshes.size());
    {
        content::Mesh lines;
        content::Material cable = material({0.35f, 0.36f, 0.38f}, 1.0f, 0.45f);
        cable.wireRadius = 0.012f;
        const int32_t cableMaterial = int32_t(meshes->model.materials.size());
        meshes->model.materials.push_back(cable);
        constexpr float kSpan = 15.0f, kSag = 0.5f;
        constexpr int kSpans = 5, kPointsPerSpan = 10;
        for (float height : {7.0f, 7.4f, 7.8f}) {
            content::Wire wire;
            wire.radius = cable.wireRadius;
            wire.material = cableMaterial;
            for (int i = 0; i <= kSpans * kPointsPerSpan; ++i) {
                const float x = -0.5f * kSpan * float(kSpans) + kSpan * float(i) / kPointsPerSpan;
                // A parabola per span: the pole ends at `height`, the middle kSag lower.
                const float u = float(i % kPointsPerSpan) / kPointsPerSpan * 2.0f - 1.0f;
                wire.positions.push_back({x, height - kSag * (1.0f - u * u), 0.0f});
                if (i > 0)
                    wire.segments.insert(wire.segments.end(), {uint32_t(i - 1), uint32_t(i)});
            }
            lines.wires.push_back(std::move(wire));
        }
        meshes->model.meshes.push_back(std::move(lines));
    }
    const int32_t pole = meshes->add(content::makeBox({0.12f, 4.0f, 0.12f}),
                                     material({0.3f, 0.22f, 0.15f}, 0.0f, 0.8f));
    // Issue 19 (Martin et al. 2014, GPU Pro 5, "TressFX: Advanced Real-Time Hair Rendering"): the
    // furry creature's body, under its fur (placed below).
    const int32_t furryBody =
        meshes->add(content::makeSphere(0.25f, 24, 12), material({0.18f, 0.1f, 0.05f}, 0.0f, 0.9f));

    // Issue 46: things that fall, tumble, bounce and roll (physics/), just inside the door.
    const int32_t crate = meshes->add(content::makeBox({0.25f, 0.25f, 0.25f}),
                                      material({0.55f, 0.38f, 0.2f}, 0.0f, 0.75f));
    const int32_t rubberBall = meshes->add(content::makeSphere(0.18f, 24, 12),
                                           material({0.85f, 0.12f, 0.08f}, 0.0f, 0.4f));
    const int32_t steelBall =
        meshes->add(content::makeSphere(0.15f, 24, 12), material({0.9f, 0.9f, 0.92f}, 1.0f, 0.2f));

    const content::Model& model = world.adoptModel(
        std::unique_ptr<content::Model>(new content::Model(std::move(meshes->model))));
    auto draw = [&](ecs::Entity e, int32_t mesh) {
        registry.emplace<content::MeshInstance>(e, content::MeshInstance{&model, mesh});
        return e;
    };

    // Architecture.
    draw(place(registry, "floor", {0.0f, 0.0f, -1.0f}), floor);
    addDemoProps(registry, draw, crate, rubberBall, steelBall);
    draw(place(registry, "runner", {0.0f, 0.01f, -0.5f}), runner);
    draw(place(registry, "back wall", {0.0f, 3.2f, -9.75f}), backWall);
    for (float side : {-1.0f, 1.0f}) {
        const float wallX = side * 6.75f, hallCentreZ = 0.5f * (kHallFrontZ + kHallBackZ);
        draw(place(registry, "side wall", {wallX, 0.5f * kWindowBottom, hallCentreZ}),
             sideWallBelow);
        draw(place(registry, "side wall", {wallX, 0.5f * (kWallTop + kWindowTop), hallCentreZ}),
             sideWallAbove);
        const float pierY = 0.5f * (kWindowBottom + kWindowTop);
        // Windows midway between the pillars: interior piers behind the pillars, end piers
        // from the first and last windows to the back and front walls.
        for (int i = 1; i < kPillarsPerRow - 1; ++i) {
            draw(place(registry, "window pier",
                       {wallX, pierY, kFirstPillarZ + kPillarSpacing * float(i)}),
                 innerPier);
        }
        const float firstWindowStart = kFirstPillarZ + 0.5f * kPillarSpacing - 0.5f * kWindowWidth;
        draw(place(registry, "window pier", {wallX, pierY, 0.5f * (kHallBackZ + firstWindowStart)}),
             endPier);
        draw(place(registry, "window pier", {wallX, pierY, kHallFrontZ - 0.5f * endPierLength}),
             endPier);
        draw(place(registry, "front wall",
                   {side * (kDoorHalfWidth + frontPieceHalfWidth), 0.5f * kWallTop,
                    kHallFrontZ + 0.125f}),
             frontWall);
        for (int i = 0; i < kPillarsPerRow; ++i) {
            float z = kFirstPillarZ + kPillarSpacing * float(i);
            float x = side * kColonnadeX;
            draw(place(registry, "pillar", {x, kPillarHeight * 0.5f, z}), pillar);
            draw(place(registry, "pillar base", {x, 0.12f, z}), plinthBlock);
            draw(place(registry, "pillar capital", {x, kPillarHeight + 0.12f, z}), plinthBlock);
        }
        draw(place(registry, "architrave", {side * kColonnadeX, kPillarHeight + 0.49f, -1.0f}),
             architrave);
    }
    for (int i = 0; i < kPillarsPerRow; ++i) {
        draw(place(registry, "roof rib",
                   {0.0f, kPillarHeight + 0.86f, kFirstPillarZ + kPillarSpacing * float(i)}),
             rib);
    }

    draw(place(registry, "door lintel",
               {0.0f, 0.5f * (kWallTop + kDoorHeight), kHallFrontZ + 0.125f}),
         lintel);
    const float roofY = kWallTop + kRoofHalfThickness;
    for (int i = 0; i + 1 < kPillarsPerRow; ++i) {
        draw(place(registry, "roof",
                   {0.0f, roofY, kFirstPillarZ + kPillarSpacing * (float(i) + 1.0f)}),
             roofPanel);
    }
    const float firstSkylightStart = kFirstPillarZ + 0.5f * kPillarSpacing - 0.5f * kSkylightWidth;
    draw(place(registry, "roof", {0.0f, roofY, 0.5f * (kHallBackZ + firstSkylightStart)}),
         endRoofPanel);
    // The last skylight lies past the last rib; the roof beyond it reaches the front wall.
    const float lastSkylightEnd =
        kFirstPillarZ + kPillarSpacing * (float(kPillarsPerRow) - 0.5f) + 0.5f * kSkylightWidth;
    if (lastSkylightEnd < kHallFrontZ) {
        draw(place(registry, "roof", {0.0f, roofY, 0.5f * (lastSkylightEnd + kHallFrontZ)}, {},
                   {1.0f, 1.0f, (kHallFrontZ - lastSkylightEnd) / endRoofLength}),
             endRoofPanel);
    }
    draw(place(registry, "meadow", {0.0f, -0.02f, 0.0f}), meadow);

    draw(place(registry, "power lines", {0.0f, 0.0f, kPowerLineZ}), powerLines);
    for (int i = 0; i <= 5; ++i) {
        draw(place(registry, "power line pole", {-37.5f + 15.0f * float(i), 4.0f, kPowerLineZ}),
             pole);
    }
    // Issue 19 (Martin et al. 2014): a furry creature by the left colonnade, fur grown on its body
    // (content::HairGrowth, as a scene file's "hair" block) and drawn by the hair pass.
    {
        const ecs::Entity creature = place(registry, "furry creature", {-2.2f, 0.3f, -4.5f});
        draw(creature, furryBody);
        content::HairGrowth fur;
        fur.count = 2500;
        fur.length = 0.09f;
        fur.seed = 19;
        fur.style.rootRadius = 0.0012f;
        fur.style.tipRadius = 0.0003f;
        fur.style.color = {0.62f, 0.38f, 0.17f};
        registry.emplace<content::HairGrowth>(creature, fur);
    }
    // The helmet on a pedestal in the middle of the hall.
    draw(place(registry, "helmet pedestal", {0.0f, 0.5f, -3.0f}), pedestal);
    draw(place(registry, "helmet pedestal top", {0.0f, 1.02f, -3.0f}), gold);
    const std::filesystem::path helmet = sharedAssets() / "models/DamagedHelmet/DamagedHelmet.glb";
    ecs::Entity helmetRoot =
        place(registry, "helmet", {0.0f, 1.65f, -3.0f},
              ecs::Quat::fromAxisAngle({0.0f, 1.0f, 0.0f}, 0.35f), {0.6f, 0.6f, 0.6f});
    world.loadGltf(helmet, diagnostics, helmetRoot);

    // A fox walking along the right colonnade, crossfading between Walk and Run.
    const std::filesystem::path fox = sharedAssets() / "models/Fox/Fox.glb";
    ecs::Entity foxRoot =
        place(registry, "fox", {2.3f, 0.0f, kFoxStartZ}, {}, {0.012f, 0.012f, 0.012f});
    registry.emplace<DemoFox>(foxRoot);
    if (world.loadGltf(fox, diagnostics, foxRoot)) {
        registry.view<content::AnimationPlayer>().each(
            [](ecs::Entity, content::AnimationPlayer& player) {
                player.play(player.findClip("Walk"));
            });
    }

    // Metal (copper) and dielectric (blue) spheres, roughness rising to the right.
    for (size_t i = 0; i < spheres.size(); ++i) {
        float x = -2.5f + 1.0f * float(i / 2);
        float z = i % 2 ? 4.4f : 3.6f;
        draw(place(registry, "sphere", {x, 0.28f, z}), spheres[i]);
    }

    draw(place(registry, "brushed metal sphere", {3.4f, 0.35f, 4.0f}), brushedSphere);
    draw(place(registry, "car paint sphere", {4.3f, 0.35f, 4.0f}), paintSphere);
    draw(place(registry, "rusty painted sphere", {5.2f, 0.35f, 4.0f}), rustySphere);

    // Toon figures (Legacy diffuse/specular): a snowman and a ball, left of the helmet.
    draw(place(registry, "toon body", {-2.3f, 0.42f, 0.0f}), toonBody);
    draw(place(registry, "toon head", {-2.3f, 1.05f, 0.0f}), toonHead);
    draw(place(registry, "toon hat", {-2.3f, 1.45f, 0.0f}), toonHat);
    draw(place(registry, "toon ball", {-1.6f, 0.3f, 0.7f}), toonBall);

    // Subsurface panels and a wax sphere, lit from behind (the side away from the path).
    const float panelYaw = -0.4f;
    for (int i = 0; i < 3; ++i) {
        ecs::Quat yaw = ecs::Quat::fromAxisAngle({0.0f, 1.0f, 0.0f}, panelYaw);
        ecs::Vec3 offset = ecs::rotate(yaw, {-0.8f + 0.8f * float(i), 0.0f, 0.0f});
        draw(place(registry, "translucent panel", ecs::Vec3{2.4f, 1.0f, 0.0f} + offset, yaw),
             i == 1 ? panelJade : panelAmber);
    }
    draw(place(registry, "wax sphere", {2.9f, 0.3f, 1.1f}), waxSphere);
    for (int i = 0; i < 2; ++i) {
        registry.emplace<content::Light>(
            place(registry, "panel backlight", {1.8f + 1.2f * float(i), 1.1f, -1.3f}),
            pointLight({1.0f, 0.85f, 0.6f}, 700.0f, 3.5f));
    }

    // Lamp bulb: a sphere light inside an emissive glass, hanging from a rib on a cord.
    content::Light bulb = pointLight({1.0f, 0.78f, 0.55f}, 1800.0f, 9.0f);
    bulb.sourceRadius = 0.08f;
    bulb.castShadows = true;
    // The dust glows around the bulb and the neon (issue 17): their volumetric scale lifts
    // the thin medium's in-scattering near them above the drifting lights' (Vos's
    // artist control, render/README.md "Volumetric lighting").
    bulb.volumetric = kDustGlow;
    ecs::Entity bulbEntity = place(registry, "lamp bulb", {-2.0f, 3.4f, -5.2f});
    registry.emplace<content::Light>(bulbEntity, bulb);
    draw(bulbEntity, bulbGlass);
    draw(place(registry, "lamp cord", {-2.0f, 4.08f, -5.2f}), cord);

    // Neon: a magenta tube across the back wall, cyan uprights on the side walls.
    content::Light magenta = pointLight({1.0f, 0.1f, 0.75f}, 2500.0f, 7.0f);
    magenta.sourceLength = 3.0f;
    magenta.sourceRadius = 0.03f;
    magenta.castShadows = true;
    magenta.volumetric = kDustGlow;
    ecs::Entity backNeon = place(registry, "neon tube", {0.0f, 5.2f, -9.4f});
    registry.emplace<content::Light>(backNeon, magenta);
    draw(backNeon, neonMagenta);
    content::Light cyan = pointLight({0.1f, 0.7f, 1.0f}, 900.0f, 5.0f);
    cyan.sourceLength = 1.6f;
    cyan.sourceRadius = 0.03f;
    cyan.castShadows = true;
    cyan.volumetric = kDustGlow;
    for (float side : {-1.0f, 1.0f}) {
        for (int i = 0; i < 3; ++i) {
            ecs::Entity e =
                place(registry, "neon upright", {side * 6.45f, 2.2f, -7.0f + 5.0f * float(i)},
                      ecs::Quat::fromAxisAngle({0.0f, 0.0f, 1.0f}, 0.5f * kPi));
            registry.emplace<content::Light>(e, cyan);
            draw(e, neonCyan);
        }
    }

    // Area lights (issue 15): disk lights on the ceiling over the aisle, their -Z turned down,
    // and a rectangle on the left wall (a window's light), its -Z turned into the hall.
    content::Light ceilingDisk = pointLight({1.0f, 0.93f, 0.82f}, 2400.0f, 8.0f);
    ceilingDisk.type = content::LightType::Disk;
    ceilingDisk.sourceRadius = 0.3f;
    // The medium lights area shapes as points shining every way (render/README.md
    // "Volumetric lighting"); at full scale the disks over the aisle would fog its top white.
    ceilingDisk.volumetric = kDustAreaLights;
    for (float z : {-2.0f, 3.5f}) {
        registry.emplace<content::Light>(
            place(registry, "ceiling disk light", {0.0f, 4.3f, z},
                  ecs::Quat::fromAxisAngle({1.0f, 0.0f, 0.0f}, -0.5f * kPi)),
            ceilingDisk);
    }
    content::Light window = pointLight({0.75f, 0.85f, 1.0f}, 3000.0f, 9.0f);
    window.type = content::LightType::Rect;
    window.width = 1.6f;
    window.height = 1.0f;
    window.volumetric = kDustAreaLights;
    registry.emplace<content::Light>(
        place(registry, "window rect light", {-6.45f, 2.4f, 1.0f},
              ecs::Quat::fromAxisAngle({0.0f, 1.0f, 0.0f}, -0.5f * kPi)),
        window);

    // A screen on the right wall facing the hall: a rect light showing a test card (a textured
    // rect, issue 15), its -Z turned to -X.
    content::Light screen = pointLight({1.0f, 1.0f, 1.0f}, 2000.0f, 8.0f);
    screen.type = content::LightType::Rect;
    screen.width = 2.0f;
    screen.height = 1.125f;
    screen.texture = content::registerLightTexture("", demoScreenImage());
    registry.emplace<content::Light>(
        place(registry, "screen rect light", {6.45f, 2.6f, 0.5f},
              ecs::Quat::fromAxisAngle({0.0f, 1.0f, 0.0f}, 0.5f * kPi)),
        screen);

    // Hundreds of coloured lights drifting through the hall; each has its own Lissajous
    // figure, so the pattern never visibly repeats within the tour.
    for (uint32_t i = 0; i < kDemoAnimatedLights; ++i) {
        const float r0 = hash01(i * 7u + 1u), r1 = hash01(i * 7u + 2u), r2 = hash01(i * 7u + 3u),
                    r3 = hash01(i * 7u + 4u), r4 = hash01(i * 7u + 5u), r5 = hash01(i * 7u + 6u);
        ecs::Entity e = place(registry, "drifting light", {});
        registry.emplace<content::Light>(
            e, pointLight(hueColor(float(i) / float(kDemoAnimatedLights)), 90.0f + 90.0f * r0,
                          1.6f + 1.0f * r1));
        DriftingLight drift;
        drift.center = {-5.0f + 10.0f * r2, 0.4f + 3.0f * r3, -8.5f + 15.0f * r4};
        drift.amplitude = {0.8f + 1.2f * r5, 0.2f + 0.5f * r0, 0.8f + 1.2f * r1};
        drift.frequency = {0.15f + 0.35f * r3, 0.3f + 0.4f * r4, 0.15f + 0.35f * r5};
        drift.phase = {2.0f * kPi * r1, 2.0f * kPi * r2, 2.0f * kPi * r0};
        registry.emplace<DriftingLight>(e, drift);
    }

    // Dust in the hall (issue 17): a thin, slightly forward-scattering medium that settles
    // (its density halves every 2 m up). It fills the hall's inside only (the box between its
    // walls, floor and roof): the meadow and the sky seen through the door and the windows
    // keep clear air.
    content::Fog dust;
    dust.scattering = 0.015f;
    dust.absorption = 0.005f;
    dust.anisotropy = 0.3f;
    dust.heightFalloff = std::numbers::ln2_v<float> / 2.0f;
    dust.bounds = content::FogBounds{{-6.5f, 0.0f, -9.5f}, {6.5f, kWallTop, kHallFrontZ}};
    registry.emplace<content::Fog>(place(registry, "dust", {}), dust);

    // The sky: Earth's atmosphere (Hillaire 2020; render/README.md "Atmosphere"), which lights
    // the scene and draws the background; its sun walks the day (demoTimeOfDay). Latitude 45
    // north at the June solstice: from 11:00 to 19:00 the sun climbs from 65 degrees in the
    // south-east over 68 at noon and sinks to 37 at 16:00 and 6.5 at 19:00 in the west,
    // shining through the skylights, then in shafts through the west windows.
    content::Atmosphere atmosphere;
    atmosphere.timeOfDay = demoTimeOfDay(0.0);
    registry.emplace<content::Atmosphere>(place(registry, "sky", {}), atmosphere);
    // The atmosphere's sun (the first directional light: its direction and illuminance come
    // from the time of day), casting shadows (render/README.md "Shadows").
    content::Light sun;
    sun.type = content::LightType::Directional;
    sun.castShadows = true;
    // Its shafts through the skylights and the windows light the hall's dust.
    sun.volumetric = kDustSunShafts;
    registry.emplace<content::Light>(place(registry, "sun", {}), sun);

    content::Camera camera;
    camera.exposureMode = content::ExposureMode::Manual;
    // Manual exposure (--exposure manual, the goldens) suits the daylight outside, where the
    // tour starts; the demo meters and adapts (auto exposure) by default.
    camera.manualEv100 = 14.0f;
    camera.verticalFov = 0.95f;
    CameraPose start = demoCameraPath().pose(0.0);
    ecs::Entity cam = place(registry, "camera", start.position, start.rotation);
    registry.emplace<content::Camera>(cam, camera);
    registry.emplace<DemoCamera>(cam);
    animateDemoLights(world, 0.0);
}

void animateDemoLights(SceneWorld& world, double seconds) {
    world.registry.view<ecs::LocalTransform, const DriftingLight>().each(
        [&](ecs::Entity e, ecs::LocalTransform& local, const DriftingLight& d) {
            const float t = float(seconds);
            local.position =
                d.center + ecs::Vec3{d.amplitude.x * std::sin(d.frequency.x * t + d.phase.x),
                                     d.amplitude.y * std::sin(d.frequency.y * t + d.phase.y),
                                     d.amplitude.z * std::sin(d.frequency.z * t + d.phase.z)};
            local.position.y = std::max(local.position.y, 0.15f);
            world.registry.markChanged<ecs::LocalTransform>(e);
        });
}

void updateDemoCamera(SceneWorld& world, const FrameContext& frame) {
    const InputState& in = frame.keys();
    ecs::Entity takeOver = ecs::kNullEntity;
    FlyCamera fly;
    world.registry.view<ecs::LocalTransform, DemoCamera>().each(
        [&](ecs::Entity e, ecs::LocalTransform& local, DemoCamera& demo) {
            if (!frame.headless && !demo.flying) {
                const bool touched = in.down(Key::W) || in.down(Key::A) || in.down(Key::S) ||
                                     in.down(Key::D) || in.down(Key::Q) || in.down(Key::E) ||
                                     in.down(MouseButton::Left) || in.down(MouseButton::Right);
                if (touched) {
                    // Take over from the path where it is: the fly camera starts from the
                    // current view direction.
                    demo.flying = true;
                    ecs::Vec3 forward = ecs::rotate(local.rotation, {0.0f, 0.0f, -1.0f});
                    fly.yaw = std::atan2(-forward.x, -forward.z);
                    fly.pitch = std::asin(std::clamp(forward.y, -1.0f, 1.0f));
                    takeOver = e;  // the component is added after the view is done
                    return;
                }
            }
            if (demo.flying) return;  // the fly camera system moves it
            CameraPose pose = demoCameraPath().pose(frame.seconds);
            local.position = pose.position;
            local.rotation = pose.rotation;
            world.registry.markChanged<ecs::LocalTransform>(e);
        });
    if (takeOver != ecs::kNullEntity) world.registry.emplace<FlyCamera>(takeOver, fly);
}

// Walk for kFoxGaitSeconds, crossfade to Run over a second, run, and back; the root moves at
// the blended gait's speed (about 0.5 m/s walking, 2 m/s running).
void walkDemoFox(SceneWorld& world, const FrameContext& frame) {
    content::AnimationPlayer* player = nullptr;
    world.registry.view<content::AnimationPlayer>().each(
        [&](ecs::Entity, content::AnimationPlayer& p) { player = &p; });
    if (player == nullptr) return;
    const std::int32_t walk = player->findClip("Walk");
    const std::int32_t run = player->findClip("Run");
    const bool wantRun = std::fmod(frame.seconds, 2.0 * kFoxGaitSeconds) >= kFoxGaitSeconds;
    const std::int32_t wanted = wantRun ? run : walk;
    const std::int32_t heading = player->nextClip >= 0 ? player->nextClip : player->clip;
    if (wanted >= 0 && heading != wanted) player->crossfade(wanted, 1.0f);
    const float runShare =
        player->nextClip >= 0
            ? (player->nextClip == run ? player->fadeWeight() : 1.0f - player->fadeWeight())
            : (player->clip == run ? 1.0f : 0.0f);
    const float speed = 0.5f + 1.5f * runShare;
    world.registry.view<DemoFox, ecs::LocalTransform>().each([&](ecs::Entity e, DemoFox& fox,
                                                                 ecs::LocalTransform& local) {
        fox.distance = std::fmod(fox.distance + speed * float(frame.deltaSeconds), kFoxPathLength);
        local.position.z = kFoxStartZ + fox.distance;
        world.registry.markChanged<ecs::LocalTransform>(e);
    });
}

void addDemoSystems(Application& app) {
    app.addSystem("demo fox", walkDemoFox);
    app.addSystem(
           "demo lights", ecs::Phase::Update,
           [](SceneWorld& world, const FrameContext& f) { animateDemoLights(world, f.seconds); })
        .reads<DriftingLight>()
        .writes<ecs::LocalTransform>();
    app.addSystem("demo day cycle", ecs::Phase::Update,
                  [](SceneWorld& world, const FrameContext& f) {
                      const float hours = demoTimeOfDay(f.seconds);
                      world.registry.view<content::Atmosphere>().each(
                          [&](ecs::Entity e, content::Atmosphere& atmosphere) {
                              atmosphere.timeOfDay = hours;
                              world.registry.markChanged<content::Atmosphere>(e);
                          });
                  })
        .writes<content::Atmosphere>();
    app.addSystem("demo camera", updateDemoCamera);
    addFlyCameraSystem(app);
}

}  // namespace candela::runtime
