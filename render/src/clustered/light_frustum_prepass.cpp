#include "clustered/light_frustum_prepass.h"
#include "lights/gpu_light_types.h"

#include <algorithm>
#include <bit>
#include <cmath>

#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

namespace candela::render {

namespace {

// Why the bound below is looser than the walk (light_assignment.cpp): in each slice the walk
// measures the sphere's cross-section (radius <= r) over depths inside
// [max(center - r, 1e-6), center + r]; x / d over that box is at most max((x + r) / dmin,
// (x + r) / dmax) and at least min((x - r) / dmin, (x - r) / dmax), and the walk drops the
// slice when that range misses [first, last] column (row) tangent. The pre-pass takes a
// padded radius so float rounding in its own view transform (relative to the magnitudes
// involved) never makes it tighter than the walk.
constexpr float kRelativePad = 1e-4f;
constexpr float kMagnitudePad = 1e-5f;

// A sphere around the one lightBoundsInView gives the walk, centred on the light's position:
// equal for points, spheres and tubes; for cones (whose walk sphere sits on the axis) the
// apex-centred sphere through it, so the bound needs no axis and holds whatever the view's
// rotation does to it.
void boundingSphere(const LightInstance& instance, glm::vec3& center, float& radius) {
    const content::Light& light = instance.light;
    const float range =
        std::max(std::isfinite(light.attenuationRadius) ? light.attenuationRadius : 0.0f, 0.0f);
    center = instance.position;
    radius = range;
    const float halfLength =
        content::isAreaLight(light.type) ? 0.0f : 0.5f * std::max(light.sourceLength, 0.0f);
    if (halfLength > 0.0f && std::isfinite(halfLength)) {
        radius = range + halfLength;
        return;
    }
    const float outer = std::clamp(light.outerConeAngle, 0.0f, 1.5707963f);
    if (gpuLightType(light.type).bounds == ClusterBounds::Cone && outer < 1.4f) {
        // Walk sphere: radius range / (2 cos) at that distance along the axis, or radius
        // range sin at range cos; apex-centred: distance plus radius.
        const float coneCos = std::cos(outer);
        radius = coneCos * coneCos >= 0.5f ? range / coneCos : range * (coneCos + std::sin(outer));
    }
}

struct FrustumEdges {
    float nearPlane, left, right, top, bottom;  // tangents x / d and y / d
};

// Bit i set when light i of the group may reach the view. Comparisons are "reject when
// outside", so NaN keeps a light and leaves the decision to the walk, as before.
#if defined(__SSE2__)
uint32_t visibleMask4(const glm::mat4& view, const FrustumEdges& edges, const float* x,
                      const float* y, const float* z, const float* r) {
    const __m128 px = _mm_loadu_ps(x), py = _mm_loadu_ps(y), pz = _mm_loadu_ps(z);
    const __m128 radius = _mm_loadu_ps(r);
    auto row = [&](int c) {
        __m128 v = _mm_mul_ps(_mm_set1_ps(view[0][c]), px);
        v = _mm_add_ps(v, _mm_mul_ps(_mm_set1_ps(view[1][c]), py));
        v = _mm_add_ps(v, _mm_mul_ps(_mm_set1_ps(view[2][c]), pz));
        return _mm_add_ps(v, _mm_set1_ps(view[3][c]));
    };
    const __m128 vx = row(0), vy = row(1);
    const __m128 depth = _mm_sub_ps(_mm_setzero_ps(), row(2));
    const __m128 far = _mm_add_ps(depth, radius);
    const __m128 near = _mm_max_ps(_mm_sub_ps(depth, radius), _mm_set1_ps(1e-6f));
    __m128 reject = _mm_cmplt_ps(far, _mm_set1_ps(edges.nearPlane));
    auto span = [&](__m128 c, float lowEdge, float highEdge) {
        const __m128 hiSide = _mm_add_ps(c, radius), loSide = _mm_sub_ps(c, radius);
        const __m128 hi = _mm_max_ps(_mm_div_ps(hiSide, near), _mm_div_ps(hiSide, far));
        const __m128 lo = _mm_min_ps(_mm_div_ps(loSide, near), _mm_div_ps(loSide, far));
        return _mm_or_ps(_mm_cmplt_ps(hi, _mm_set1_ps(lowEdge)),
                         _mm_cmpgt_ps(lo, _mm_set1_ps(highEdge)));
    };
    reject = _mm_or_ps(reject, span(vx, edges.left, edges.right));
    reject = _mm_or_ps(reject, span(vy, edges.bottom, edges.top));
    return uint32_t(~_mm_movemask_ps(reject)) & 0xfu;
}
#else
uint32_t visibleMask4(const glm::mat4& view, const FrustumEdges& edges, const float* x,
                      const float* y, const float* z, const float* r) {
    uint32_t mask = 0;
    for (int i = 0; i < 4; ++i) {
        const glm::vec3 v = glm::vec3(view * glm::vec4(x[i], y[i], z[i], 1.0f));
        const float depth = -v.z, far = depth + r[i];
        const float near = std::max(depth - r[i], 1e-6f);
        auto outside = [&](float c, float lowEdge, float highEdge) {
            const float hi = std::max((c + r[i]) / near, (c + r[i]) / far);
            const float lo = std::min((c - r[i]) / near, (c - r[i]) / far);
            return hi < lowEdge || lo > highEdge;
        };
        const bool reject = far < edges.nearPlane || outside(v.x, edges.left, edges.right) ||
                            outside(v.y, edges.bottom, edges.top);
        if (!reject) mask |= 1u << i;
    }
    return mask;
}
#endif

}  // namespace

void lightsInFrustum(const ClusterGrid& grid, std::span<const LightInstance> lights, size_t first,
                     size_t last, const glm::mat4& view, LightFrustumScratch& s,
                     std::vector<uint32_t>& visible) {
    s.x.clear();
    s.y.clear();
    s.z.clear();
    s.radius.clear();
    s.index.clear();
    const float translationScale =
        std::abs(view[3][0]) + std::abs(view[3][1]) + std::abs(view[3][2]);
    for (size_t i = first; i < last; ++i) {
        if (inEveryCluster(lights[i].light)) continue;
        glm::vec3 center;
        float radius;
        boundingSphere(lights[i], center, radius);
        const float magnitude =
            std::abs(center.x) + std::abs(center.y) + std::abs(center.z) + translationScale;
        s.x.push_back(center.x);
        s.y.push_back(center.y);
        s.z.push_back(center.z);
        s.radius.push_back(radius + kRelativePad * (1.0f + radius) + kMagnitudePad * magnitude);
        s.index.push_back(uint32_t(i));
    }
    const size_t count = s.index.size();
    const size_t padded = (count + 3) & ~size_t(3);
    s.x.resize(padded, 0.0f);
    s.y.resize(padded, 0.0f);
    s.z.resize(padded, 0.0f);
    s.radius.resize(padded, 0.0f);
    const FrustumEdges edges{grid.nearPlane, grid.columnTangent.front(), grid.columnTangent.back(),
                             grid.rowTangent.front(), grid.rowTangent.back()};
    for (size_t i = 0; i < padded; i += 4) {
        uint32_t mask = visibleMask4(view, edges, &s.x[i], &s.y[i], &s.z[i], &s.radius[i]);
        for (; mask; mask &= mask - 1) {
            const size_t lane = i + size_t(std::countr_zero(mask));
            if (lane < count) visible.push_back(s.index[lane]);
        }
    }
}

}  // namespace candela::render
