// Hair strands (content/hair.h): the root-to-tip parameter of line primitives, and hair
// generated on a mesh's surface.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "candela/content/hair.h"
#include "candela/content/model.h"

namespace candela::content {

namespace {

using Float3 = std::array<float, 3>;

float distance(const Float3& a, const Float3& b) {
    const float x = a[0] - b[0], y = a[1] - b[1], z = a[2] - b[2];
    return std::sqrt(x * x + y * y + z * z);
}

// A small deterministic generator (splitmix64): the same seed gives the same hair on every
// platform, which std::uniform_real_distribution does not promise.
class SplitMix {
public:
    explicit SplitMix(std::uint64_t seed) : state_(seed) {}
    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    float uniform() { return float(next() >> 40) * (1.0f / float(1u << 24)); }  // [0, 1)

private:
    std::uint64_t state_;
};

}  // namespace

std::vector<float> strandParameters(const std::vector<Float3>& positions,
                                    const std::vector<std::uint32_t>& segments) {
    // next[a] = b for each segment a -> b; a position nothing points to is a root.
    std::unordered_map<std::uint32_t, std::uint32_t> next;
    std::vector<bool> hasParent(positions.size(), false);
    for (std::size_t i = 0; i + 1 < segments.size(); i += 2) {
        next.emplace(segments[i], segments[i + 1]);
        hasParent[segments[i + 1]] = true;
    }
    std::vector<float> parameter(positions.size(), 0.0f);
    std::vector<bool> visited(positions.size(), false);
    std::vector<std::uint32_t> strand;
    std::vector<float> arc;
    for (std::uint32_t root = 0; root < positions.size(); ++root) {
        if (hasParent[root] || !next.contains(root)) continue;
        strand.assign(1, root);
        arc.assign(1, 0.0f);
        visited[root] = true;
        for (auto it = next.find(root); it != next.end() && !visited[it->second];
             it = next.find(it->second)) {
            visited[it->second] = true;
            arc.push_back(arc.back() + distance(positions[strand.back()], positions[it->second]));
            strand.push_back(it->second);
        }
        const float length = arc.back();
        for (std::size_t i = 0; i < strand.size(); ++i)
            parameter[strand[i]] = length > 0.0f ? arc[i] / length : 0.0f;
    }
    return parameter;
}

Hair generateHair(const Primitive& surface, std::uint32_t count, float length, std::uint32_t seed,
                  std::uint32_t pointsPerStrand) {
    Hair hair;
    pointsPerStrand = std::max(pointsPerStrand, 2u);
    // Area-weighted choice of triangle: the cumulative areas.
    std::vector<double> cumulative;
    const auto& p = surface.positions;
    for (std::size_t t = 0; t + 2 < surface.indices.size(); t += 3) {
        const Float3& a = p[surface.indices[t]];
        const Float3& b = p[surface.indices[t + 1]];
        const Float3& c = p[surface.indices[t + 2]];
        const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
        const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
        const double cx = uy * vz - uz * vy, cy = uz * vx - ux * vz, cz = ux * vy - uy * vx;
        const double area = 0.5 * std::sqrt(cx * cx + cy * cy + cz * cz);
        cumulative.push_back((cumulative.empty() ? 0.0 : cumulative.back()) + area);
    }
    if (cumulative.empty() || !(cumulative.back() > 0.0) || count == 0) return hair;
    SplitMix random(0x6a09e667f3bcc909ull ^ seed);
    for (std::uint32_t s = 0; s < count; ++s) {
        const double pick = random.uniform() * cumulative.back();
        const std::size_t triangle = std::size_t(
            std::upper_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin());
        const std::size_t t = 3 * std::min(triangle, cumulative.size() - 1);
        // A uniform point of the triangle (the square folded onto it).
        float u = random.uniform(), v = random.uniform();
        if (u + v > 1.0f) u = 1.0f - u, v = 1.0f - v;
        const std::uint32_t i0 = surface.indices[t], i1 = surface.indices[t + 1],
                            i2 = surface.indices[t + 2];
        Float3 root{}, normal{};
        for (int k = 0; k < 3; ++k) {
            root[k] = p[i0][k] + u * (p[i1][k] - p[i0][k]) + v * (p[i2][k] - p[i0][k]);
            normal[k] = surface.normals.size() == p.size()
                            ? (1 - u - v) * surface.normals[i0][k] + u * surface.normals[i1][k] +
                                  v * surface.normals[i2][k]
                            : 0.0f;
        }
        float n = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
        if (!(n > 1e-12f)) normal = {0.0f, 1.0f, 0.0f}, n = 1.0f;
        // Lean: a random sideways direction that grows along the strand (a gentle curve) and a
        // droop along -Y, so strands do not stand like needles.
        Float3 lean{random.uniform() - 0.5f, random.uniform() - 0.5f, random.uniform() - 0.5f};
        const std::uint32_t first = std::uint32_t(hair.positions.size());
        Float3 point = root;
        Float3 direction{normal[0] / n, normal[1] / n, normal[2] / n};
        const float step = length / float(pointsPerStrand - 1);
        hair.positions.push_back(point);
        for (std::uint32_t k = 1; k < pointsPerStrand; ++k) {
            for (int c = 0; c < 3; ++c)
                direction[c] += 0.35f * lean[c] - (c == 1 ? 0.15f : 0.0f);
            const float d = std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] +
                                      direction[2] * direction[2]);
            for (int c = 0; c < 3; ++c)
                point[c] += step * direction[c] / d;
            hair.positions.push_back(point);
            hair.segments.insert(hair.segments.end(), {first + k - 1, first + k});
        }
    }
    hair.rootToTip = strandParameters(hair.positions, hair.segments);
    return hair;
}

}  // namespace candela::content
