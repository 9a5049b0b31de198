#include "orb_level.h"

#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "candela/content/components/animation.h"
#include "candela/content/components/audio_source.h"
#include "candela/content/components/collider.h"
#include "candela/content/components/light.h"
#include "candela/content/components/mesh_instance.h"
#include "candela/content/components/rigid_body.h"
#include "candela/content/components/scene_components.h"
#include "candela/content/model_lookup.h"
#include "candela/content/procedural_mesh.h"
#include "candela/ecs/transform.h"
#include "orb_components.h"

namespace orb {

namespace {

using candela::ecs::Entity;
using candela::ecs::Vec3;
using nlohmann::json;

candela::content::Material glow(std::array<float, 3> radiance) {
    candela::content::Material m;
    m.shadingModel = candela::content::ShadingModel::Unlit;
    m.baseColorFactor = {0.0f, 0.0f, 0.0f, 1.0f};
    m.emissiveFactor = radiance;
    return m;
}

// One sphere mesh per glow colour, in one model kept alive by the world.
struct GlowMeshes {
    std::unique_ptr<candela::content::Model> model = std::make_unique<candela::content::Model>();
    int32_t add(float radius, std::array<float, 3> radiance) {
        candela::content::Primitive sphere = candela::content::makeSphere(radius, 32, 16);
        sphere.material = int32_t(model->materials.size());
        model->materials.push_back(glow(radiance));
        candela::content::Mesh mesh;
        mesh.primitives.push_back(std::move(sphere));
        model->meshes.push_back(std::move(mesh));
        return int32_t(model->meshes.size() - 1);
    }
};

float number(const json& j, const char* key, float fallback) {
    auto it = j.find(key);
    return it != j.end() && it->is_number() ? it->get<float>() : fallback;
}

candela::content::Collider sphere(float radius, bool trigger) {
    candela::content::Collider collider;
    collider.shape = candela::content::ColliderShape::Sphere;
    collider.radius = radius;
    collider.trigger = trigger;
    return collider;
}

// Floating (no gravity), frictionless against the walls, keeping half its speed into a wall
// when it bounces (the pair takes the larger restitution: the walls have none).
candela::content::RigidBody floatingBody() {
    candela::content::RigidBody body;
    body.friction = 0.0f;
    body.restitution = 0.5f;
    body.gravityScale = 0.0f;
    body.angularDamping = 0.0f;
    body.canSleep = false;
    return body;
}

bool point(const json& j, const char* key, Vec3& out) {
    auto it = j.find(key);
    if (it == j.end() || !it->is_array() || it->size() != 3) return false;
    for (const json& v : *it)
        if (!v.is_number()) return false;
    out = {(*it)[0].get<float>(), (*it)[1].get<float>(), (*it)[2].get<float>()};
    return true;
}

// A spark is collected when the orb's sphere touches this sphere around it.
constexpr float kPickupReach = 0.15f;

}  // namespace

const char* statusName(Status status) {
    switch (status) {
        case Status::Playing:
            return "playing";
        case Status::Won:
            return "won";
        case Status::Lost:
            return "lost";
        case Status::Title:
            return "title";
    }
    return "?";
}

std::string spawnLevel(candela::runtime::SceneWorld& world, const std::string& levelName) {
    auto& registry = world.registry;
    struct Tagged {
        Entity entity;
        json data;
    };
    std::vector<Tagged> tagged;
    std::string error;
    registry.view<const candela::content::GameData>().each(
        [&](Entity e, const candela::content::GameData& data) {
            json parsed = json::parse(data.json, nullptr, false);
            if (parsed.is_discarded() || !parsed.is_object() || !parsed["role"].is_string()) {
                if (error.empty()) error = levelName + ": gameData without a \"role\" string";
                return;
            }
            tagged.push_back({e, std::move(parsed)});
        });
    if (!error.empty()) return error;

    GlowMeshes meshes;
    const int32_t orbMesh = meshes.add(0.3f, {60.0f, 45.0f, 25.0f});
    const int32_t hazardMesh = meshes.add(0.3f, {80.0f, 3.0f, 1.0f});
    auto lightOf = [&](Entity e) { return registry.tryGet<candela::content::Light>(e); };

    int orbs = 0, rules = 0;
    std::vector<std::pair<Entity, int32_t>> draws;
    for (Tagged& t : tagged) {
        const std::string role = t.data["role"].get<std::string>();
        auto* local = registry.tryGet<candela::ecs::LocalTransform>(t.entity);
        if (!local && role != "rules") {
            return levelName + ": the " + role + " entity has no transform";
        }
        if (role == "orb") {
            Orb orb;
            orb.acceleration = number(t.data, "acceleration", orb.acceleration);
            orb.maxSpeed = number(t.data, "maxSpeed", orb.maxSpeed);
            orb.radius = number(t.data, "radius", orb.radius);
            orb.start = local->position;
            registry.emplace<Orb>(t.entity, orb);
            registry.emplace<candela::content::Collider>(t.entity, sphere(orb.radius, false));
            registry.emplace<candela::content::RigidBody>(t.entity, floatingBody());
            draws.emplace_back(t.entity, orbMesh);
            ++orbs;
        } else if (role == "pickup") {
            Pickup pickup;
            pickup.points = int32_t(number(t.data, "points", 10.0f));
            pickup.home = local->position;
            const candela::content::Light* light = lightOf(t.entity);
            if (!light) return levelName + ": a pickup needs a light (it is the thing to see)";
            pickup.lumens = light->lumens;
            registry.emplace<Pickup>(t.entity, pickup);
            registry.emplace<candela::content::Collider>(t.entity, sphere(kPickupReach, true));
            // Each spark glows in its light's colour.
            const std::array<float, 3>& c = light->color;
            draws.emplace_back(t.entity,
                               meshes.add(0.12f, {c[0] * 40.0f, c[1] * 40.0f, c[2] * 40.0f}));
        } else if (role == "hazard") {
            Hazard hazard;
            if (!point(t.data, "from", hazard.from) || !point(t.data, "to", hazard.to)) {
                return levelName + ": a hazard needs \"from\" and \"to\" points [x, y, z]";
            }
            hazard.speed = number(t.data, "speed", hazard.speed);
            hazard.radius = number(t.data, "radius", hazard.radius);
            registry.emplace<Hazard>(t.entity, hazard);
            registry.emplace<candela::content::Collider>(t.entity, sphere(hazard.radius, true));
            draws.emplace_back(t.entity, hazardMesh);
        } else if (role == "wall") {
            // The level draws walls with the unit box, which a box collider fits by itself.
            registry.emplace<candela::content::Collider>(t.entity);
        } else if (role == "rules") {
            GameState state;
            state.timeLimitSeconds = number(t.data, "timeLimitSeconds", state.timeLimitSeconds);
            registry.emplace<GameState>(t.entity, state);
            ++rules;
        } else if (role == "sound") {
            if (!t.data["plays"].is_string() ||
                !registry.has<candela::content::AudioSource>(t.entity)) {
                return levelName + ": a sound needs \"plays\" and an audioSource";
            }
            registry.emplace<SoundCue>(t.entity, SoundCue{t.data["plays"].get<std::string>()});
        } else {
            return levelName + ": unknown gameData role '" + role + "'";
        }
    }
    if (orbs != 1) return levelName + ": needs exactly one orb, found " + std::to_string(orbs);
    if (rules != 1) {
        return levelName + ": needs exactly one \"rules\" entity, found " + std::to_string(rules);
    }
    const candela::content::Model& model = world.adoptModel(std::move(meshes.model));
    for (auto [e, mesh] : draws) {
        registry.emplace<candela::content::MeshInstance>(
            e, candela::content::MeshInstance{&model, mesh, {}});
    }
    int32_t total = 0;
    registry.view<const Pickup>().each([&](const Pickup&) { ++total; });
    registry.view<GameState>().each([&](GameState& s) { s.total = total; });
    return {};
}

std::string spawnMascot(candela::runtime::SceneWorld& world, const std::string& modelPath,
                        candela::content::Diagnostics& diagnostics) {
    using candela::content::AnimationPlayer;
    // On the north wall's middle, facing the player (+Z); sized for a fox of about 1 m.
    candela::ecs::LocalTransform at;
    at.position = {0.0f, 1.0f, -6.25f};
    at.scale = {0.02f, 0.02f, 0.02f};
    const Entity root = world.spawn("mascot", at);
    if (!world.loadGltf(modelPath, diagnostics, root))
        return modelPath + ": cannot load the mascot";
    Mascot mascot;
    mascot.player = candela::content::findAnimationPlayer(world.registry, root);
    if (mascot.player == candela::ecs::kNullEntity)
        return modelPath + ": the mascot has no animation clips";
    // The Fox's clips by name; any other model: its first, last and second clip.
    const AnimationPlayer& player = world.registry.get<AnimationPlayer>(mascot.player);
    const auto clip = [&](const char* name, std::int32_t fallback) {
        const std::int32_t found = player.findClip(name);
        return found >= 0 ? found : fallback;
    };
    const auto count = static_cast<std::int32_t>(player.model->animations.size());
    mascot.idleClip = clip("Survey", 0);
    mascot.cheerClip = clip("Run", count - 1);
    mascot.sulkClip = clip("Walk", count > 1 ? 1 : 0);
    world.registry.get<AnimationPlayer>(mascot.player).play(mascot.idleClip);
    world.registry.emplace<Mascot>(root, std::move(mascot));
    return {};
}

}  // namespace orb
