#include "candela/runtime/scene_world.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "candela/content/components/camera.h"
#include "candela/content/components/collider.h"
#include "candela/content/components/light.h"
#include "candela/content/components/mesh_instance.h"
#include "candela/content/components/name.h"
#include "candela/content/components/sky.h"
#include "candela/content/gltf_loader.h"
#include "candela/content/model_instantiation.h"
#include "candela/content/scene_file.h"
#include "candela/content/scene_instantiation.h"
#include "candela/ecs/transform.h"
#include "candela/ecs/transform_propagation.h"
#include "candela/ecs/view.h"
#include "candela/runtime/debug_text.h"
#include "unmarked_changes.h"

namespace candela::runtime {

namespace {

ecs::Vec3 transformPoint(const ecs::Mat4& m, const content::Float3& p) {
    return {m(0, 0) * p[0] + m(0, 1) * p[1] + m(0, 2) * p[2] + m(0, 3),
            m(1, 0) * p[0] + m(1, 1) * p[1] + m(1, 2) * p[2] + m(1, 3),
            m(2, 0) * p[0] + m(2, 1) * p[1] + m(2, 2) * p[2] + m(2, 3)};
}

// A rotation whose -Z axis points along `forward` (normalised) with +Y as close to up as
// possible: how cameras and lights are aimed.
ecs::Quat lookRotation(ecs::Vec3 forward) {
    ecs::Vec3 f = forward * (1.0f / ecs::length(forward));
    ecs::Vec3 up{0.0f, 1.0f, 0.0f};
    if (std::abs(ecs::dot(f, up)) > 0.999f) up = {0.0f, 0.0f, -1.0f};
    ecs::Vec3 x = ecs::cross(up, ecs::Vec3{-f.x, -f.y, -f.z});
    x = x * (1.0f / ecs::length(x));
    ecs::Vec3 z{-f.x, -f.y, -f.z};
    ecs::Vec3 y = ecs::cross(z, x);
    // Rotation matrix columns x, y, z -> quaternion.
    float trace = x.x + y.y + z.z;
    ecs::Quat q;
    if (trace > 0.0f) {
        float s = std::sqrt(trace + 1.0f) * 2.0f;
        q = {(y.z - z.y) / s, (z.x - x.z) / s, (x.y - y.x) / s, 0.25f * s};
    } else if (x.x > y.y && x.x > z.z) {
        float s = std::sqrt(1.0f + x.x - y.y - z.z) * 2.0f;
        q = {0.25f * s, (y.x + x.y) / s, (z.x + x.z) / s, (y.z - z.y) / s};
    } else if (y.y > z.z) {
        float s = std::sqrt(1.0f + y.y - x.x - z.z) * 2.0f;
        q = {(y.x + x.y) / s, 0.25f * s, (z.y + y.z) / s, (z.x - x.z) / s};
    } else {
        float s = std::sqrt(1.0f + z.z - x.x - y.y) * 2.0f;
        q = {(z.x + x.z) / s, (z.y + y.z) / s, 0.25f * s, (x.y - y.x) / s};
    }
    return ecs::normalize(q);
}

ecs::Entity addAimedEntity(ecs::Registry& registry, const std::string& name, ecs::Vec3 position,
                           ecs::Vec3 forward) {
    ecs::Entity e = registry.create();
    registry.emplace<content::Name>(e, content::Name{name});
    ecs::LocalTransform local;
    local.position = position;
    local.rotation = lookRotation(forward);
    registry.emplace<ecs::LocalTransform>(e, local);
    registry.emplace<ecs::WorldTransform>(e);
    return e;
}

}  // namespace

const content::Model& SceneWorld::adoptModel(std::unique_ptr<content::Model> model) {
    models_.push_back(std::move(model));
    return *models_.back();
}

bool SceneWorld::loadGltf(const std::filesystem::path& path, content::Diagnostics& diagnostics,
                          ecs::Entity parent) {
    std::optional<content::Model> model = content::loadGltf(path, diagnostics);
    if (!model) return false;
    const content::Model& kept = adoptModel(std::make_unique<content::Model>(std::move(*model)));
    content::instantiateModel(registry, kept, parent);
    return true;
}

bool SceneWorld::loadSceneFile(const std::filesystem::path& path,
                               content::Diagnostics& diagnostics) {
    std::optional<content::SceneDocument> scene = content::loadSceneFile(path, diagnostics);
    if (!scene) return false;
    content::instantiateScene(registry, *scene, path, cache_, diagnostics);
    sceneFile_ = path;
    sceneSettings_ = scene->settings;
    sceneQuality_ = scene->quality;
    sceneAmbientOcclusion_ = scene->ambientOcclusion;
    sceneMaterialLayers_ = scene->materialLayers;
    return true;
}

std::filesystem::path SceneWorld::resolveAssetPath(const std::string& stored) const {
    if (sceneFile_.empty()) return stored;
    return content::resolveScenePath(sceneFile_, stored);
}

DebugText& debugText(SceneWorld& world) {
    return world.registry.resources().getOrEmplace<DebugText>();
}

struct SceneWorld::FrameChecks {
    UnmarkedChangeCheck<content::Light> lights{"Light"};
    UnmarkedChangeCheck<ecs::LocalTransform> transforms{"LocalTransform"};
};

SceneWorld::SceneWorld() : checks_(std::make_unique<FrameChecks>()) {}
SceneWorld::~SceneWorld() = default;

ecs::Entity SceneWorld::spawn(const std::string& name, const ecs::LocalTransform& at) {
    const ecs::Entity e = registry.create();
    if (!name.empty()) registry.emplace<content::Name>(e, content::Name{name});
    registry.emplace<ecs::LocalTransform>(e, at);
    registry.emplace<ecs::WorldTransform>(e);
    return e;
}

namespace {

// Entities with T but no WorldTransform, gathered first: adding inside a walk is refused.
template <class T>
void collectUnplaced(ecs::Registry& registry, std::vector<ecs::Entity>& out) {
    registry.view<const T>(ecs::exclude<ecs::WorldTransform>).each([&](ecs::Entity e, const T&) {
        out.push_back(e);
    });
}

}  // namespace

physics::PhysicsWorld& SceneWorld::physics() {
    if (!physics_) physics_ = std::make_unique<physics::PhysicsWorld>(registry, physicsSettings);
    return *physics_;
}

void SceneWorld::stepPhysics(double deltaSeconds) {
    if (!physics_ && registry.view<content::Collider>().empty()) return;
    physics::PhysicsWorld& world = physics();
    if (simulatePhysics) {
        world.update(deltaSeconds);
    } else {
        world.sync();
    }
    content::Diagnostics& said = world.diagnostics();
    for (const content::Diagnostic& d : said.messages)
        std::fprintf(stderr, "%s\n", content::formatDiagnostic(d).c_str());
    said.messages.clear();
}

void SceneWorld::updateTransforms() {
    std::vector<ecs::Entity> unplaced;
    collectUnplaced<content::MeshInstance>(registry, unplaced);
    collectUnplaced<content::Light>(registry, unplaced);
    collectUnplaced<content::Camera>(registry, unplaced);
    for (ecs::Entity e : unplaced) {
        if (registry.has<ecs::WorldTransform>(e)) continue;  // had two of the three
        if (!registry.has<ecs::LocalTransform>(e)) registry.emplace<ecs::LocalTransform>(e);
        registry.emplace<ecs::WorldTransform>(e);
    }
    if (checkUnmarkedChanges) {
        checks_->lights.run(registry);
        checks_->transforms.run(registry);
    }
    ecs::propagateTransforms(registry);
    if (checkUnmarkedChanges) checks_->transforms.notePropagated(registry.currentTick());
}

SceneBounds SceneWorld::bounds() {
    updateTransforms();
    SceneBounds b;
    registry.view<const ecs::WorldTransform, const content::MeshInstance>().each(
        [&](const ecs::WorldTransform& world, const content::MeshInstance& instance) {
            if (!instance.model || instance.mesh < 0 ||
                size_t(instance.mesh) >= instance.model->meshes.size()) {
                return;
            }
            for (const content::Primitive& p : instance.model->meshes[instance.mesh].primitives) {
                for (int corner = 0; corner < 8; ++corner) {
                    content::Float3 local = {corner & 1 ? p.boundsMax[0] : p.boundsMin[0],
                                             corner & 2 ? p.boundsMax[1] : p.boundsMin[1],
                                             corner & 4 ? p.boundsMax[2] : p.boundsMin[2]};
                    ecs::Vec3 v = transformPoint(world.matrix, local);
                    const float xyz[3] = {v.x, v.y, v.z};
                    for (int i = 0; i < 3; ++i) {
                        if (!std::isfinite(xyz[i])) continue;
                        b.min[i] = b.empty ? xyz[i] : std::min(b.min[i], xyz[i]);
                        b.max[i] = b.empty ? xyz[i] : std::max(b.max[i], xyz[i]);
                    }
                    b.empty = false;
                }
            }
        });
    return b;
}

std::vector<std::string> SceneWorld::addViewingDefaults(bool externalSky) {
    std::vector<std::string> added;
    SceneBounds b = bounds();
    ecs::Vec3 center{0.0f, 0.0f, 0.0f};
    float radius = 1.0f;
    if (!b.empty) {
        center = {(b.min[0] + b.max[0]) * 0.5f, (b.min[1] + b.max[1]) * 0.5f,
                  (b.min[2] + b.max[2]) * 0.5f};
        ecs::Vec3 half{b.max[0] - center.x, b.max[1] - center.y, b.max[2] - center.z};
        radius = std::max(ecs::length(half), 1e-3f);
    }

    bool hasCamera = false, hasLight = false, hasSky = externalSky;
    registry.view<const content::Camera>().each([&](const content::Camera&) { hasCamera = true; });
    registry.view<const content::Light>().each([&](const content::Light&) { hasLight = true; });
    registry.view<const content::Sky>().each([&](const content::Sky&) { hasSky = true; });

    if (!hasCamera) {
        content::Camera camera;  // 50 degree vertical field of view, sunny-16 exposure
        float distance = radius / std::sin(camera.verticalFov * 0.5f) * 1.1f;
        ecs::Vec3 direction{0.55f, 0.35f, 0.75f};
        direction = direction * (1.0f / ecs::length(direction));
        ecs::Entity e = addAimedEntity(registry, "default camera", center + direction * distance,
                                       ecs::Vec3{-direction.x, -direction.y, -direction.z});
        camera.nearPlane = std::max(distance - radius * 1.5f, radius * 1e-3f);
        registry.emplace<content::Camera>(e, camera);
        added.push_back("the scene has no camera: added a default camera framing its bounds");
    }
    if (!hasLight && !hasSky) {
        // Daylight under the sunny-16 exposure: a sun of 100,000 lux and a sky-like fill.
        content::Light sun;
        sun.type = content::LightType::Directional;
        sun.lux = 100000.0f;
        sun.color = {1.0f, 0.96f, 0.9f};
        ecs::Entity s = addAimedEntity(registry, "default sun", center, {-0.4f, -0.8f, -0.45f});
        registry.emplace<content::Light>(s, sun);
        content::Light fill = sun;
        fill.lux = 25000.0f;
        fill.color = {0.6f, 0.75f, 1.0f};
        ecs::Entity f = addAimedEntity(registry, "default fill", center, {0.6f, 0.2f, -0.5f});
        registry.emplace<content::Light>(f, fill);
        added.push_back(
            "the scene has neither lights nor a sky: added a default sun of 100000 lux and a "
            "fill of 25000 lux (pass --env SKY.exr to light it with a sky instead)");
    }
    updateTransforms();
    return added;
}

}  // namespace candela::runtime
