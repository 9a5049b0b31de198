#include "candela/content/procedural_mesh.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace candela::content {

namespace {

void computeBounds(Primitive& p) {
    p.boundsMin = p.positions.front();
    p.boundsMax = p.positions.front();
    for (const Float3& v : p.positions) {
        for (int i = 0; i < 3; ++i) {
            p.boundsMin[i] = std::min(p.boundsMin[i], v[i]);
            p.boundsMax[i] = std::max(p.boundsMax[i], v[i]);
        }
    }
}

}  // namespace

Primitive makePlane(float halfExtent, uint32_t subdivisions) {
    subdivisions = std::max(subdivisions, 1u);
    Primitive p;
    const uint32_t side = subdivisions + 1;
    for (uint32_t z = 0; z < side; ++z) {
        for (uint32_t x = 0; x < side; ++x) {
            float u = float(x) / float(subdivisions);
            float v = float(z) / float(subdivisions);
            p.positions.push_back(
                {(u * 2.0f - 1.0f) * halfExtent, 0.0f, (v * 2.0f - 1.0f) * halfExtent});
            p.normals.push_back({0.0f, 1.0f, 0.0f});
            p.tangents.push_back({1.0f, 0.0f, 0.0f, 1.0f});
            p.uv0.push_back({u, v});
        }
    }
    for (uint32_t z = 0; z < subdivisions; ++z) {
        for (uint32_t x = 0; x < subdivisions; ++x) {
            uint32_t i = z * side + x;
            // Counter-clockwise seen from +Y.
            p.indices.insert(p.indices.end(), {i, i + side, i + 1, i + 1, i + side, i + side + 1});
        }
    }
    computeBounds(p);
    return p;
}

Primitive makeSphere(float radius, uint32_t segments, uint32_t rings) {
    segments = std::max(segments, 3u);
    rings = std::max(rings, 2u);
    const float pi = std::numbers::pi_v<float>;
    Primitive p;
    for (uint32_t r = 0; r <= rings; ++r) {
        float v = float(r) / float(rings);
        float theta = v * pi;  // from +Y down
        for (uint32_t s = 0; s <= segments; ++s) {
            float u = float(s) / float(segments);
            float phi = u * 2.0f * pi;
            Float3 n = {std::sin(theta) * std::cos(phi), std::cos(theta),
                        -std::sin(theta) * std::sin(phi)};
            p.positions.push_back({n[0] * radius, n[1] * radius, n[2] * radius});
            p.normals.push_back(n);
            // d(position)/d(phi), normalised; at the poles any horizontal direction will do.
            p.tangents.push_back({-std::sin(phi), 0.0f, -std::cos(phi), 1.0f});
            p.uv0.push_back({u, v});
        }
    }
    const uint32_t row = segments + 1;
    for (uint32_t r = 0; r < rings; ++r) {
        for (uint32_t s = 0; s < segments; ++s) {
            uint32_t i = r * row + s;
            p.indices.insert(p.indices.end(), {i, i + row, i + 1, i + 1, i + row, i + row + 1});
        }
    }
    computeBounds(p);
    return p;
}

Primitive makeBox(const Float3& h) {
    Primitive p;
    // Each face: outward normal n, tangent t, bitangent b = n x t; corners at n +- t +- b.
    const Float3 faces[6][3] = {
        {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
    };
    for (const auto& face : faces) {
        const Float3& n = face[0];
        const Float3& t = face[1];
        const Float3& b = face[2];
        uint32_t base = uint32_t(p.positions.size());
        const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (const auto& c : corners) {
            Float3 position;
            for (int i = 0; i < 3; ++i)
                position[i] = (n[i] + t[i] * c[0] + b[i] * c[1]) * h[i];
            p.positions.push_back(position);
            p.normals.push_back(n);
            p.tangents.push_back({t[0], t[1], t[2], 1.0f});
            p.uv0.push_back({(c[0] + 1.0f) * 0.5f, 1.0f - (c[1] + 1.0f) * 0.5f});
        }
        p.indices.insert(p.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    computeBounds(p);
    return p;
}

}  // namespace candela::content
