#include "app/light_gizmo.h"

#include <cmath>
#include <cstring>
#include <glm/glm.hpp>
#include <optional>

#include "candela/content/components/light.h"
#include "candela/content/light_types.h"
#include "candela/ecs/transform.h"
#include "model/editor_scene.h"

namespace candela::editor {

namespace {

constexpr ImU32 kRadiusColour = IM_COL32(255, 210, 80, 200);
constexpr ImU32 kInnerColour = IM_COL32(255, 210, 80, 110);
constexpr ImU32 kSourceColour = IM_COL32(255, 255, 255, 230);
constexpr int kCircleSegments = 64;

class Projector {
public:
    Projector(const render::CameraView& camera, ImVec2 size)
        : viewProjection_(camera.projection * camera.view), size_(size), near_(camera.nearPlane) {}

    // Screen position, or nothing when the point is behind the near plane.
    std::optional<ImVec2> project(const glm::vec3& p) const {
        const glm::vec4 clip = viewProjection_ * glm::vec4(p, 1.0f);
        if (clip.w < near_) return std::nullopt;
        // Vulkan clip space: y already points down.
        return ImVec2((clip.x / clip.w * 0.5f + 0.5f) * size_.x,
                      (clip.y / clip.w * 0.5f + 0.5f) * size_.y);
    }

    void line(ImDrawList* list, const glm::vec3& a, const glm::vec3& b, ImU32 colour) const {
        const auto pa = project(a);
        const auto pb = project(b);
        if (pa && pb) list->AddLine(*pa, *pb, colour, 1.5f);
    }

    // Circle of `radius` around `center` in the plane spanned by unit vectors u and v.
    void circle(ImDrawList* list, const glm::vec3& center, const glm::vec3& u, const glm::vec3& v,
                float radius, ImU32 colour) const {
        glm::vec3 previous = center + u * radius;
        for (int i = 1; i <= kCircleSegments; ++i) {
            const float a = 2.0f * 3.14159265f * float(i) / float(kCircleSegments);
            const glm::vec3 next = center + (u * std::cos(a) + v * std::sin(a)) * radius;
            line(list, previous, next, colour);
            previous = next;
        }
    }

private:
    glm::mat4 viewProjection_;
    ImVec2 size_;
    float near_;
};

glm::vec3 column(const glm::mat4& m, int c) {
    const glm::vec3 v(m[c]);
    const float length = glm::length(v);
    return length > 0.0f && std::isfinite(length) ? v / length : glm::vec3(0.0f);
}

// Any unit vector perpendicular to unit `axis`.
glm::vec3 perpendicular(const glm::vec3& axis) {
    const glm::vec3 other = std::abs(axis.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    return glm::normalize(glm::cross(axis, other));
}

void drawSelectedLight(const Projector& projector, ImDrawList* list, const content::Light& light,
                       const glm::mat4& world) {
    const glm::vec3 position(world[3]);
    const glm::vec3 x = column(world, 0), y = column(world, 1), z = column(world, 2);
    const glm::vec3 forward = -z;  // spots and directional lights shine along -Z
    const float radius = light.attenuationRadius;

    // The reach outline the light type table (content/light_types.h) gives the type.
    switch (content::lightTypeInfo(light.type).outline) {
        case content::LightOutline::FalloffSphere:
            projector.circle(list, position, x, y, radius, kRadiusColour);
            projector.circle(list, position, x, z, radius, kRadiusColour);
            projector.circle(list, position, y, z, radius, kRadiusColour);
            break;
        case content::LightOutline::Cone: {
            // The cone out to the attenuation radius: its end cap circle and four edges.
            for (float angle : {light.outerConeAngle, light.innerConeAngle}) {
                const ImU32 colour = angle == light.outerConeAngle ? kRadiusColour : kInnerColour;
                const glm::vec3 capCenter = position + forward * (radius * std::cos(angle));
                const float capRadius = radius * std::sin(angle);
                projector.circle(list, capCenter, x, y, capRadius, colour);
                for (const glm::vec3& edge : {x, -x, y, -y}) {
                    projector.line(list, position, capCenter + edge * capRadius, colour);
                }
            }
            break;
        }
        case content::LightOutline::Direction:
            projector.line(list, position, position + forward * 2.0f, kRadiusColour);
            projector.circle(list, position + forward * 2.0f, x, y, 0.15f, kRadiusColour);
            break;
        case content::LightOutline::Rect:
        case content::LightOutline::Disk: {
            // The emitting shape in the node's XY plane, its normal (-Z, the lit side) and
            // the half of the falloff sphere it can reach.
            if (content::lightTypeInfo(light.type).outline == content::LightOutline::Rect) {
                const glm::vec3 hx = x * (0.5f * light.width), hy = y * (0.5f * light.height);
                const glm::vec3 corners[4] = {position - hx - hy, position + hx - hy,
                                              position + hx + hy, position - hx + hy};
                for (int i = 0; i < 4; ++i)
                    projector.line(list, corners[i], corners[(i + 1) % 4], kSourceColour);
            } else {
                projector.circle(list, position, x, y, light.sourceRadius, kSourceColour);
            }
            projector.line(list, position, position + forward * 0.5f, kSourceColour);
            projector.circle(list, position, x, y, radius, kRadiusColour);
            return;  // no sphere or tube source
        }
    }

    // Source shape: a sphere (three circles), or a tube along local +X, capsule-shaped when it
    // also has a radius.
    const float r = light.sourceRadius;
    const float halfLength = light.sourceLength * 0.5f;
    if (halfLength > 0.0f) {
        const glm::vec3 a = position - x * halfLength;
        const glm::vec3 b = position + x * halfLength;
        projector.line(list, a, b, kSourceColour);
        if (r > 0.0f) {
            const glm::vec3 u = perpendicular(x), v = glm::cross(x, u);
            projector.circle(list, a, u, v, r, kSourceColour);
            projector.circle(list, b, u, v, r, kSourceColour);
            for (const glm::vec3& side : {u, -u, v, -v}) {
                projector.line(list, a + side * r, b + side * r, kSourceColour);
            }
        }
    } else if (r > 0.0f) {
        projector.circle(list, position, x, y, r, kSourceColour);
        projector.circle(list, position, x, z, r, kSourceColour);
        projector.circle(list, position, y, z, r, kSourceColour);
    }
}

}  // namespace

void drawLightGizmos(EditorScene& scene, const render::CameraView& camera, ImVec2 displaySize,
                     ImDrawList* drawList) {
    const Projector projector(camera, displaySize);
    const uint64_t selected = scene.selectedId();
    scene.registry().view<const content::Light, const ecs::WorldTransform>().each(
        [&](ecs::Entity e, const content::Light& light, const ecs::WorldTransform& transform) {
            glm::mat4 world;
            std::memcpy(&world[0][0], transform.matrix.m, sizeof(transform.matrix.m));
            if (scene.idOf(e) == selected) {
                drawSelectedLight(projector, drawList, light, world);
            } else if (auto p = projector.project(glm::vec3(world[3]))) {
                drawList->AddCircle(*p, 5.0f, kInnerColour, 12, 1.5f);
            }
        });
}

}  // namespace candela::editor
