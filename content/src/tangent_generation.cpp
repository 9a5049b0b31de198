#include "candela/content/tangent_generation.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_map>

#include "primitive_vertices.h"

namespace candela::content {
namespace {

Float3 sub(const Float3& a, const Float3& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
float dot(const Float3& a, const Float3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Float3 scaled(const Float3& a, float s) {
    return {a[0] * s, a[1] * s, a[2] * s};
}
Float3 add(const Float3& a, const Float3& b) {
    return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}

// v minus its component along unit n, normalised; false when nothing is left.
bool projectOntoPlane(const Float3& v, const Float3& n, Float3& out) {
    out = sub(v, scaled(n, dot(n, v)));
    const float length = std::sqrt(dot(out, out));
    if (!(length > 1e-20f) || !std::isfinite(length)) return false;
    out = scaled(out, 1.0f / length);
    return true;
}

// Vertices that are equal in position, normal and UV form one MikkTSpace vertex even when
// the file stores them under different indices.
std::vector<std::uint32_t> weldedRepresentatives(const Primitive& p,
                                                 const std::vector<Float2>& uv) {
    struct Key {
        std::array<std::uint32_t, 8> bits;
        bool operator==(const Key&) const = default;
    };
    struct KeyHash {
        std::size_t operator()(const Key& k) const {
            std::size_t h = 1469598103934665603ull;
            for (std::uint32_t b : k.bits)
                h = (h ^ b) * 1099511628211ull;
            return h;
        }
    };
    std::unordered_map<Key, std::uint32_t, KeyHash> first;
    first.reserve(p.positions.size());
    std::vector<std::uint32_t> representative(p.positions.size());
    for (std::uint32_t v = 0; v < p.positions.size(); ++v) {
        const float values[8] = {p.positions[v][0], p.positions[v][1], p.positions[v][2],
                                 p.normals[v][0],   p.normals[v][1],   p.normals[v][2],
                                 uv[v][0],          uv[v][1]};
        Key key;
        std::memcpy(key.bits.data(), values, sizeof(values));
        representative[v] = first.try_emplace(key, v).first->second;
    }
    return representative;
}

// Angle of the triangle corner at `at`, between the edges projected onto the normal plane
// (MikkTSpace weighs by this angle so a vertex's tangent does not depend on tessellation).
float cornerAngle(const Float3& at, const Float3& next, const Float3& previous, const Float3& n) {
    Float3 a;
    Float3 b;
    if (!projectOntoPlane(sub(next, at), n, a) || !projectOntoPlane(sub(previous, at), n, b)) {
        return 0.0f;
    }
    return std::acos(std::clamp(dot(a, b), -1.0f, 1.0f));
}

void fillWithoutUvs(Primitive& p) {
    p.tangents.resize(p.positions.size());
    for (std::size_t v = 0; v < p.positions.size(); ++v) {
        const Float3 t = anyPerpendicular(p.normals[v]);
        p.tangents[v] = {t[0], t[1], t[2], 1.0f};
    }
}

}  // namespace

void generateTangents(Primitive& p, std::uint32_t uvSet) {
    p.tangentsGenerated = true;
    const std::vector<Float2>& uvStream = uvSet == 1 ? p.uv1 : p.uv0;
    if (p.normals.size() != p.positions.size()) return;  // callers generate normals first
    if (uvStream.size() != p.positions.size()) {
        fillWithoutUvs(p);
        return;
    }
    const std::vector<Float2> uv = uvStream;  // stable copy: splitting vertices grows streams
    const std::size_t vertexCount = p.positions.size();
    const std::size_t triangleCount = p.indices.size() / 3;
    const std::vector<std::uint32_t> representative = weldedRepresentatives(p, uv);

    // Accumulated tangent per (welded vertex, winding): index 2 * vertex + (mirrored ? 1 : 0).
    std::vector<Float3> sum(2 * vertexCount, Float3{0, 0, 0});
    std::vector<std::uint8_t> cornerMirrored(p.indices.size(), 0);
    for (std::size_t t = 0; t < triangleCount; ++t) {
        const std::uint32_t* corner = &p.indices[3 * t];
        const Float3& p0 = p.positions[corner[0]];
        const Float3 e1 = sub(p.positions[corner[1]], p0);
        const Float3 e2 = sub(p.positions[corner[2]], p0);
        const float du1 = uv[corner[1]][0] - uv[corner[0]][0];
        const float dv1 = uv[corner[1]][1] - uv[corner[0]][1];
        const float du2 = uv[corner[2]][0] - uv[corner[0]][0];
        const float dv2 = uv[corner[2]][1] - uv[corner[0]][1];
        const float signedUvArea = du1 * dv2 - du2 * dv1;
        // glTF's v runs down the image while MikkTSpace assumes v up (Blender's exporter feeds
        // it 1 - v; three.js negates w "for glTF"), so the winding is judged on (u, -v).
        const bool mirrored = signedUvArea > 0;
        // dP/du times the signed UV area; dividing out the area's sign leaves dP/du's direction
        // (only the direction matters), the same for both windings.
        Float3 tangent = sub(scaled(e1, dv2), scaled(e2, dv1));
        if (signedUvArea < 0) tangent = scaled(tangent, -1.0f);
        const bool degenerate = signedUvArea == 0 || !std::isfinite(signedUvArea);
        for (int k = 0; k < 3; ++k) {
            cornerMirrored[3 * t + k] = mirrored ? 1 : 0;
            if (degenerate) continue;  // takes its tangent from its neighbours
            const std::uint32_t v = corner[k];
            Float3 projected;
            if (!projectOntoPlane(tangent, p.normals[v], projected)) continue;
            const float weight = cornerAngle(p.positions[v], p.positions[corner[(k + 1) % 3]],
                                             p.positions[corner[(k + 2) % 3]], p.normals[v]);
            Float3& accumulated = sum[2 * representative[v] + (mirrored ? 1 : 0)];
            accumulated = add(accumulated, scaled(projected, weight));
        }
    }

    // Resolve per corner; a vertex whose corners disagree on winding is split.
    p.tangents.assign(vertexCount, Float4{0, 0, 0, 0});
    std::vector<std::int64_t> splitCopy(vertexCount, -1);  // vertex -> its mirrored-side copy
    std::vector<std::int8_t> windingOf(vertexCount, -1);   // -1 unassigned, 0 normal, 1 mirrored
    for (std::size_t c = 0; c < p.indices.size(); ++c) {
        std::uint32_t v = p.indices[c];
        const std::uint8_t mirrored = cornerMirrored[c];
        const std::uint32_t rep = representative[v];
        Float3 direction;
        const Float3& own = sum[2 * rep + mirrored];
        const Float3& other = sum[2 * rep + (1 - mirrored)];
        if (!projectOntoPlane(own, p.normals[v], direction) &&
            !projectOntoPlane(other, p.normals[v], direction)) {
            direction = anyPerpendicular(p.normals[v]);
        }
        const Float4 tangent{direction[0], direction[1], direction[2], mirrored ? -1.0f : 1.0f};
        if (windingOf[v] == -1) {
            windingOf[v] = static_cast<std::int8_t>(mirrored);
            p.tangents[v] = tangent;
        } else if (windingOf[v] != static_cast<std::int8_t>(mirrored)) {
            if (splitCopy[v] < 0) {
                splitCopy[v] = appendVertexCopy(p, v);  // also copies the tangent slot
                p.tangents.back() = tangent;
            }
            p.indices[c] = static_cast<std::uint32_t>(splitCopy[v]);
        }
    }
    // Vertices no triangle uses still get a valid tangent.
    for (std::size_t v = 0; v < vertexCount; ++v) {
        if (windingOf[v] == -1) {
            const Float3 t = anyPerpendicular(p.normals[v]);
            p.tangents[v] = {t[0], t[1], t[2], 1.0f};
        }
    }
}

}  // namespace candela::content
