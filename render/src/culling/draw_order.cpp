#include "culling/draw_order.h"

#include <algorithm>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "culling/draws_in_view.h"

namespace candela::render {

std::vector<uint32_t> nearestFirst(std::span<const uint8_t> visible,
                                   std::span<const WorldBounds> bounds, const glm::vec3& eye) {
    struct Keyed {
        float distanceSquared;
        uint32_t draw;
    };
    std::vector<Keyed> keyed;
    keyed.reserve(visible.size());
    for (uint32_t i = 0; i < visible.size(); ++i) {
        if (visible[i] == kDrawCulled) continue;
        float distanceSquared = 0.0f;
        if (i < bounds.size()) {
            const glm::vec3 outside =
                glm::max(glm::abs(eye - bounds[i].centre) - bounds[i].extent, glm::vec3(0.0f));
            distanceSquared = glm::dot(outside, outside);
        }
        // A box that is not finite (a draw with a NaN transform) goes last.
        if (!(distanceSquared >= 0.0f && distanceSquared <= 3.0e38f)) distanceSquared = 3.0e38f;
        keyed.push_back({distanceSquared, i});
    }
    std::stable_sort(keyed.begin(), keyed.end(), [](const Keyed& a, const Keyed& b) {
        return a.distanceSquared < b.distanceSquared;
    });
    std::vector<uint32_t> order;
    order.reserve(keyed.size());
    for (const Keyed& k : keyed)
        order.push_back(k.draw);
    return order;
}

}  // namespace candela::render
