#include "clustered/light_bounds.h"

#include <algorithm>
#include <cmath>

#include "lights/gpu_light_types.h"

namespace candela::render {

namespace {

// Float slack added to every distance comparison, relative to the light's size, so rounding
// in the view transform never culls a light whose window is still (barely) non-zero.
float slack(float radius) {
    return 1e-4f * (1.0f + radius);
}

float distanceSqPointBox(const glm::vec3& p, const glm::vec3& lo, const glm::vec3& hi) {
    glm::vec3 d = glm::max(glm::max(lo - p, p - hi), glm::vec3(0.0f));
    return glm::dot(d, d);
}

// Minimum distance from segment a..b to the box: the distance is convex along the segment,
// so a ternary search converges; the remaining bracket is added back to stay conservative.
float distanceSegmentBox(const glm::vec3& a, const glm::vec3& b, const glm::vec3& lo,
                         const glm::vec3& hi) {
    float t0 = 0.0f, t1 = 1.0f;
    auto f = [&](float t) { return std::sqrt(distanceSqPointBox(a + (b - a) * t, lo, hi)); };
    for (int i = 0; i < 24; ++i) {
        float m0 = t0 + (t1 - t0) / 3.0f, m1 = t1 - (t1 - t0) / 3.0f;
        if (f(m0) < f(m1)) {
            t1 = m1;
        } else {
            t0 = m0;
        }
    }
    float bracket = glm::length(b - a) * (t1 - t0);
    return std::max(f(0.5f * (t0 + t1)) - bracket, 0.0f);
}

}  // namespace

LightBounds lightBoundsInView(const LightInstance& instance, const glm::mat4& view) {
    const content::Light& light = instance.light;
    LightBounds b;
    const float range =
        std::max(std::isfinite(light.attenuationRadius) ? light.attenuationRadius : 0.0f, 0.0f);
    const glm::vec3 position = glm::vec3(view * glm::vec4(instance.position, 1.0f));
    // Area lights have no tube (packLight writes their sourceLength as 0).
    const float halfLength =
        content::isAreaLight(light.type) ? 0.0f : 0.5f * std::max(light.sourceLength, 0.0f);
    if (halfLength > 0.0f && std::isfinite(halfLength)) {
        glm::vec3 axis = glm::normalize(glm::mat3(view) * instance.tubeAxis);
        b.shape = LightShape::Capsule;
        b.segmentStart = position - axis * halfLength;
        b.segmentEnd = position + axis * halfLength;
        b.capsuleRadius = range;
        b.center = position;
        b.radius = range + halfLength;
        return b;
    }
    b.center = position;
    b.radius = range;
    if (gpuLightType(light.type).bounds == ClusterBounds::HalfSpace) {
        // As packLight: a unit normal, -Z when the direction is degenerate.
        const float lengthSq = glm::dot(instance.direction, instance.direction);
        const glm::vec3 normal = std::isfinite(lengthSq) && lengthSq >= 1e-20f
                                     ? instance.direction / std::sqrt(lengthSq)
                                     : glm::vec3(0.0f, 0.0f, -1.0f);
        b.shape = LightShape::HalfSphere;
        b.segmentEnd = glm::mat3(view) * normal;
        return b;
    }
    const float outer = std::clamp(light.outerConeAngle, 0.0f, 1.5707963f);
    // Spots narrower than ~80 degrees get the cone test; wider ones gain little from it.
    if (gpuLightType(light.type).bounds == ClusterBounds::Cone && outer < 1.4f) {
        glm::vec3 axis = glm::normalize(glm::mat3(view) * instance.direction);
        b.shape = LightShape::Cone;
        b.segmentStart = position;
        b.segmentEnd = axis;
        b.capsuleRadius = range;
        b.coneCos = std::cos(outer);
        b.coneSin = std::sin(outer);
        // Smallest sphere around the cone (apex, axis, range, half-angle).
        if (b.coneCos * b.coneCos >= 0.5f) {
            b.radius = range / (2.0f * b.coneCos);
            b.center = position + axis * b.radius;
        } else {
            b.radius = range * b.coneSin;
            b.center = position + axis * (range * b.coneCos);
        }
    }
    return b;
}

bool lightTouchesBox(const LightBounds& b, const glm::vec3& lo, const glm::vec3& hi) {
    switch (b.shape) {
        case LightShape::Sphere: {
            float r = b.radius + slack(b.radius);
            return distanceSqPointBox(b.center, lo, hi) <= r * r;
        }
        case LightShape::HalfSphere: {
            float r = b.radius + slack(b.radius);
            if (distanceSqPointBox(b.center, lo, hi) > r * r) return false;
            // The box corner furthest along the normal, against the light's plane.
            const glm::vec3 n = b.segmentEnd;
            const glm::vec3 corner(n.x >= 0.0f ? hi.x : lo.x, n.y >= 0.0f ? hi.y : lo.y,
                                   n.z >= 0.0f ? hi.z : lo.z);
            return glm::dot(n, corner - b.center) >= -slack(b.radius);
        }
        case LightShape::Capsule:
            return distanceSegmentBox(b.segmentStart, b.segmentEnd, lo, hi) <=
                   b.capsuleRadius + slack(b.radius);
        case LightShape::Cone: {
            float r = b.radius + slack(b.radius);
            if (distanceSqPointBox(b.center, lo, hi) > r * r) return false;
            // The box's bounding sphere against the cone (sphere-vs-cone with a flat cap).
            glm::vec3 boxCenter = 0.5f * (lo + hi);
            float boxRadius = 0.5f * glm::length(hi - lo) + slack(b.radius);
            glm::vec3 v = boxCenter - b.segmentStart;
            float along = glm::dot(v, b.segmentEnd);
            float across = std::sqrt(std::max(glm::dot(v, v) - along * along, 0.0f));
            float outsideCone = b.coneCos * across - along * b.coneSin;
            if (outsideCone > boxRadius) return false;
            if (along > b.capsuleRadius + boxRadius) return false;
            return along >= -boxRadius;
        }
    }
    return true;
}

uint32_t boundingShapeTouchesBoxes(const LightBounds& b, const float* boxes, uint32_t count,
                                   float padPerDepth) {
    // Spheres (and capsules' bounding spheres) inline: this runs four times per listed pair.
    const float r = paddedBoundingRadius(b);
    uint32_t touched = 0;
    for (uint32_t i = 0; i < count; ++i) {
        const float* box = boxes + 6 * i;
        if (box[0] > box[3]) continue;  // empty
        const glm::vec3 lo(box[0], box[1], box[2]), hi(box[3], box[4], box[5]);
        const glm::vec3 pad(padPerDepth * (1.0f - lo.z));
        const bool reached = b.shape == LightShape::Cone
                                 ? lightTouchesBox(b, lo - pad, hi + pad)
                                 : distanceSqPointBox(b.center, lo - pad, hi + pad) <= r * r;
        touched |= reached ? 1u << i : 0u;
    }
    return touched;
}

float paddedBoundingRadius(const LightBounds& b) {
    return b.radius + slack(b.radius);
}

bool lightReachesPositiveSide(const LightBounds& b, const glm::vec3& n) {
    if (b.shape == LightShape::Capsule) {
        float nearest = std::max(glm::dot(n, b.segmentStart), glm::dot(n, b.segmentEnd));
        return nearest >= -(b.capsuleRadius + slack(b.radius));
    }
    return glm::dot(n, b.center) >= -(b.radius + slack(b.radius));
}

}  // namespace candela::render
