// glTF meshes -> Model::meshes: triangle lists with validated attributes and indices,
// generated normals/tangents where missing. A primitive that cannot be used is skipped with
// a message; the rest of the mesh still loads.
#include <algorithm>
#include <cmath>

#include "candela/content/hair.h"
#include "candela/content/normal_generation.h"
#include "candela/content/tangent_generation.h"
#include "gltf_accessors.h"
#include "gltf_context.h"

namespace candela::content::gltf {
namespace {

template <std::size_t N>
std::vector<std::array<float, N>> packed(const std::vector<float>& flat) {
    std::vector<std::array<float, N>> out(flat.size() / N);
    for (std::size_t i = 0; i < out.size(); ++i) {
        std::copy_n(flat.begin() + static_cast<std::ptrdiff_t>(i * N), N, out[i].begin());
    }
    return out;
}

bool allFinite(const std::vector<float>& values) {
    return std::all_of(values.begin(), values.end(), [](float v) { return std::isfinite(v); });
}

// Reads an optional attribute with N components. Missing or unusable data leaves `out` empty
// (with a message when it was there but broken).
template <std::size_t N>
void readAttribute(Context& context, const std::string& element, const tinygltf::Primitive& source,
                   const char* name, std::size_t vertexCount, const AccessorLimits& limits,
                   std::vector<std::array<float, N>>& out) {
    auto it = source.attributes.find(name);
    if (it == source.attributes.end()) return;
    std::vector<float> flat;
    if (std::string error = readFloats(context.document, it->second, N, flat, limits);
        !error.empty()) {
        context.error(element, std::string(name) + ": " + error + "; attribute ignored");
        return;
    }
    if (flat.size() != vertexCount * N) {
        context.error(element, std::string(name) + " has " + std::to_string(flat.size() / N) +
                                   " elements but POSITION has " + std::to_string(vertexCount) +
                                   "; attribute ignored");
        return;
    }
    if (!allFinite(flat)) {
        context.warning(element, std::string(name) + " has NaN/Inf values; attribute ignored");
        return;
    }
    out = packed<N>(flat);
}

void readColors(Context& context, const std::string& element, const tinygltf::Primitive& source,
                std::size_t vertexCount, const AccessorLimits& limits, Primitive& primitive) {
    auto it = source.attributes.find("COLOR_0");
    if (it == source.attributes.end()) return;
    if (!validIndex(it->second, context.document.accessors)) {
        context.error(element, "COLOR_0 accessor " + std::to_string(it->second) +
                                   " does not exist; attribute ignored");
        return;
    }
    if (componentCount(context.document.accessors[static_cast<std::size_t>(it->second)].type) ==
        3) {
        std::vector<Float3> rgb;
        readAttribute<3>(context, element, source, "COLOR_0", vertexCount, limits, rgb);
        primitive.colors.reserve(rgb.size());
        for (const Float3& c : rgb)
            primitive.colors.push_back({c[0], c[1], c[2], 1.0f});
    } else {
        readAttribute<4>(context, element, source, "COLOR_0", vertexCount, limits,
                         primitive.colors);
    }
}

// Triangle strips and fans become lists (glTF 2.0 section 3.7.2.1 gives the vertex order).
std::vector<std::uint32_t> toTriangleList(const std::vector<std::uint32_t>& in, int mode) {
    if (mode == TINYGLTF_MODE_TRIANGLES || in.size() < 3) return in;
    std::vector<std::uint32_t> out;
    out.reserve((in.size() - 2) * 3);
    for (std::size_t i = 0; i + 2 < in.size(); ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            const std::size_t odd = i % 2;
            out.insert(out.end(), {in[i], in[i + 1 + odd], in[i + 2 - odd]});
        } else {  // fan
            out.insert(out.end(), {in[i + 1], in[i + 2], in[0]});
        }
    }
    return out;
}

void computeBounds(Primitive& primitive) {
    Float3 lo = primitive.positions.front();
    Float3 hi = lo;
    for (const Float3& p : primitive.positions) {
        for (int c = 0; c < 3; ++c) {
            lo[c] = std::min(lo[c], p[c]);
            hi[c] = std::max(hi[c], p[c]);
        }
    }
    primitive.boundsMin = lo;
    primitive.boundsMax = hi;
}

// The UV set a material's normal map reads, which is the one tangents must follow.
std::uint32_t tangentUvSet(const Context& context, std::int32_t material) {
    if (material < 0) return 0;
    const TextureRef& normal =
        context.model.materials[static_cast<std::size_t>(material)].normalTexture;
    return normal.present() ? normal.texCoord : 0;
}

// A primitive's vertex indices: its index accessor's, each checked below `vertexCount`, or
// 0 to vertexCount - 1 without one. Unset after an error naming `what` ("primitive", "wire",
// "hair") as skipped.
std::optional<std::vector<std::uint32_t>> readVertexIndices(Context& context,
                                                            const tinygltf::Primitive& source,
                                                            const std::string& element,
                                                            const std::string& what,
                                                            std::uint64_t vertexCount) {
    std::vector<std::uint32_t> indices;
    if (source.indices >= 0 || source.indices < -1) {
        const GltfLoadOptions& options = context.options;
        std::uint64_t indexCount = 0;
        std::string error = accessorCount(context.document, source.indices, indexCount);
        if (error.empty() && indexCount > options.maxIndicesPerPrimitive) {
            error = std::to_string(indexCount) + " indices exceed the limit";
        }
        if (error.empty()) {
            error = readIndices(context.document, source.indices, indices,
                                AccessorLimits{options.maxElementsWithoutBufferView});
        }
        if (!error.empty()) {
            context.error(element, "indices: " + error + "; " + what + " skipped");
            return std::nullopt;
        }
        for (std::size_t i = 0; i < indices.size(); ++i) {
            if (indices[i] >= vertexCount) {
                context.error(element, "index " + std::to_string(indices[i]) + " at position " +
                                           std::to_string(i) + " is not below the vertex count " +
                                           std::to_string(vertexCount) + "; " + what + " skipped");
                return std::nullopt;
            }
        }
    } else {
        indices.resize(vertexCount);
        for (std::uint32_t i = 0; i < vertexCount; ++i)
            indices[i] = i;
    }
    return indices;
}

std::optional<Primitive> convertPrimitive(Context& context, const tinygltf::Primitive& source,
                                          const std::string& element) {
    const GltfLoadOptions& options = context.options;
    const AccessorLimits limits{options.maxElementsWithoutBufferView};
    if (source.mode != TINYGLTF_MODE_TRIANGLES && source.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        source.mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        context.warning(element, "mode " + std::to_string(source.mode) +
                                     " (points/lines) is not supported; primitive skipped");
        return std::nullopt;
    }
    auto position = source.attributes.find("POSITION");
    if (position == source.attributes.end()) {
        context.error(element, "has no POSITION attribute; primitive skipped");
        return std::nullopt;
    }
    std::uint64_t vertexCount = 0;
    if (std::string error = accessorCount(context.document, position->second, vertexCount);
        !error.empty() || vertexCount == 0 || vertexCount > options.maxVerticesPerPrimitive) {
        context.error(
            element,
            "POSITION: " +
                (error.empty() ? std::to_string(vertexCount) + " vertices is outside [1, " +
                                     std::to_string(options.maxVerticesPerPrimitive) + "]"
                               : error) +
                "; primitive skipped");
        return std::nullopt;
    }
    std::vector<float> flat;
    if (std::string error = readFloats(context.document, position->second, 3, flat, limits);
        !error.empty()) {
        context.error(element, "POSITION: " + error + "; primitive skipped");
        return std::nullopt;
    }
    if (!allFinite(flat)) {
        context.error(element, "POSITION has NaN/Inf values; primitive skipped");
        return std::nullopt;
    }
    Primitive primitive;
    primitive.positions = packed<3>(flat);

    std::optional<std::vector<std::uint32_t>> indices =
        readVertexIndices(context, source, element, "primitive", vertexCount);
    if (!indices) return std::nullopt;
    primitive.indices = toTriangleList(*indices, source.mode);
    if (primitive.indices.size() % 3 != 0) {
        context.warning(element, std::to_string(primitive.indices.size() % 3) +
                                     " trailing indices do not form a triangle; dropped");
        primitive.indices.resize(primitive.indices.size() / 3 * 3);
    }
    if (primitive.indices.empty()) {
        context.warning(element, "has no triangles; primitive skipped");
        return std::nullopt;
    }

    const std::size_t count = static_cast<std::size_t>(vertexCount);
    readAttribute<3>(context, element, source, "NORMAL", count, limits, primitive.normals);
    readAttribute<4>(context, element, source, "TANGENT", count, limits, primitive.tangents);
    readAttribute<2>(context, element, source, "TEXCOORD_0", count, limits, primitive.uv0);
    readAttribute<2>(context, element, source, "TEXCOORD_1", count, limits, primitive.uv1);
    readColors(context, element, source, count, limits, primitive);
    readSkinAttributes(context, element, source, count, limits, primitive);
    readMorphTargets(context, element, source, count, limits, primitive);

    if (source.material >= 0 || source.material < -1) {
        if (validIndex(source.material, context.model.materials)) {
            primitive.material = source.material;
        } else {
            context.error(element, "material " + std::to_string(source.material) +
                                       " does not exist; using the default material");
        }
    }

    if (primitive.normals.empty()) {
        primitive.tangents.clear();  // tangents without normals have no frame to live in
        generateFlatNormals(primitive);
    } else {
        for (Float3& n : primitive.normals) {
            const float length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            n = length > 1e-20f ? Float3{n[0] / length, n[1] / length, n[2] / length}
                                : Float3{0, 1, 0};
        }
    }
    if (primitive.tangents.empty() && options.generateTangents) {
        generateTangents(primitive, tangentUvSet(context, primitive.material));
    }
    if (primitive.normalsGenerated) {
        for (MorphTarget& target : primitive.morphTargets)
            target.normalDeltas.clear();  // flat normals follow no authored deltas
    }
    computeBounds(primitive);
    return primitive;
}

bool isLineMode(int mode) {
    return mode == TINYGLTF_MODE_LINE || mode == TINYGLTF_MODE_LINE_STRIP ||
           mode == TINYGLTF_MODE_LINE_LOOP;
}

// Lines, strips and loops become index pairs (glTF 2.0 section 3.7.2.1).
std::vector<std::uint32_t> toSegments(const std::vector<std::uint32_t>& in, int mode) {
    if (mode == TINYGLTF_MODE_LINE) return in;
    std::vector<std::uint32_t> out;
    for (std::size_t i = 0; i + 1 < in.size(); ++i)
        out.insert(out.end(), {in[i], in[i + 1]});
    if (mode == TINYGLTF_MODE_LINE_LOOP && in.size() > 2) out.insert(out.end(), {in.back(), in[0]});
    return out;
}

// A line primitive's positions and segments (index pairs), shared by wires and hair. `what`
// names the result in messages ("wire", "hair").
struct LinePrimitive {
    std::vector<std::array<float, 3>> positions;
    std::vector<std::uint32_t> segments;
};
std::optional<LinePrimitive> readLines(Context& context, const tinygltf::Primitive& source,
                                       const std::string& element, const std::string& what) {
    const GltfLoadOptions& options = context.options;
    const AccessorLimits limits{options.maxElementsWithoutBufferView};
    auto position = source.attributes.find("POSITION");
    if (position == source.attributes.end()) {
        context.error(element, "has no POSITION attribute; " + what + " skipped");
        return std::nullopt;
    }
    std::vector<float> flat;
    if (std::string error = readFloats(context.document, position->second, 3, flat, limits);
        !error.empty() || flat.empty() || flat.size() / 3 > options.maxVerticesPerPrimitive) {
        context.error(element, "POSITION: " + (error.empty() ? "no or too many vertices" : error) +
                                   "; " + what + " skipped");
        return std::nullopt;
    }
    if (!allFinite(flat)) {
        context.error(element, "POSITION has NaN/Inf values; " + what + " skipped");
        return std::nullopt;
    }
    LinePrimitive lines;
    lines.positions = packed<3>(flat);
    std::optional<std::vector<std::uint32_t>> indices =
        readVertexIndices(context, source, element, what, lines.positions.size());
    if (!indices) return std::nullopt;
    lines.segments = toSegments(*indices, source.mode);
    lines.segments.resize(lines.segments.size() / 2 * 2);
    if (lines.segments.empty()) {
        context.warning(element, "has no line segment; " + what + " skipped");
        return std::nullopt;
    }
    return lines;
}

// A line primitive whose material has extras.wireRadius: a wire (Persson 2014, GPU Pro 5, "Wire
// Antialiasing").
std::optional<Wire> convertWire(Context& context, const tinygltf::Primitive& source,
                                const std::string& element, std::int32_t material, float radius) {
    auto lines = readLines(context, source, element, "wire");
    if (!lines) return std::nullopt;
    Wire wire;
    wire.positions = std::move(lines->positions);
    wire.segments = std::move(lines->segments);
    wire.radius = radius;
    wire.material = material;
    return wire;
}

// A line primitive whose material has extras.hair: hair strands (Martin et al. 2014, GPU Pro 5,
// "TressFX: Advanced Real-Time Hair Rendering"), each segment pointing from root toward tip as the
// file orders it.
std::optional<Hair> convertHair(Context& context, const tinygltf::Primitive& source,
                                const std::string& element, std::int32_t material) {
    auto lines = readLines(context, source, element, "hair");
    if (!lines) return std::nullopt;
    Hair hair;
    hair.positions = std::move(lines->positions);
    hair.segments = std::move(lines->segments);
    hair.rootToTip = strandParameters(hair.positions, hair.segments);
    hair.material = material;
    return hair;
}

// Lines: hair when the material has extras.hair, a wire when it has extras.wireRadius; others
// are skipped with a warning, as points are.
void convertLines(Context& context, const tinygltf::Primitive& source, const std::string& element,
                  Mesh& mesh) {
    const std::int32_t material =
        validIndex(source.material, context.model.materials) ? source.material : kNoIndex;
    const Material* m = material == kNoIndex
                            ? nullptr
                            : &context.model.materials[static_cast<std::size_t>(material)];
    if (m != nullptr && m->hair) {
        if (source.mode == TINYGLTF_MODE_LINE_LOOP) {
            context.warning(element, "a line loop has no root or tip; hair skipped");
        } else if (auto hair = convertHair(context, source, element, material)) {
            mesh.hair.push_back(std::move(*hair));
        }
        return;
    }
    if (m == nullptr || m->wireRadius <= 0.0f) {
        context.warning(element, "mode " + std::to_string(source.mode) +
                                     " (lines) is not supported without a material whose "
                                     "extras.wireRadius makes it a wire or extras.hair hair; "
                                     "primitive skipped");
        return;
    }
    if (auto wire = convertWire(context, source, element, material, m->wireRadius)) {
        mesh.wires.push_back(std::move(*wire));
    }
}

// glTF requires every primitive of a mesh to have the same number of targets and the mesh's
// weights to match it; otherwise the morph data is unusable and is dropped.
void checkMorphTargetCounts(Context& context, const std::string& element, Mesh& mesh) {
    std::size_t targets = 0;
    for (const Primitive& p : mesh.primitives)
        targets = std::max(targets, p.morphTargets.size());
    bool consistent = mesh.defaultWeights.empty() || mesh.defaultWeights.size() == targets;
    for (const Primitive& p : mesh.primitives)
        consistent = consistent && p.morphTargets.size() == targets;
    if (!consistent) {
        context.error(element,
                      "primitives and weights disagree on the morph target count; "
                      "morph targets dropped");
        for (Primitive& p : mesh.primitives)
            p.morphTargets.clear();
        mesh.defaultWeights.clear();
        return;
    }
    mesh.defaultWeights.resize(targets, 0.0f);
}

}  // namespace

void convertMeshes(Context& context) {
    const auto& meshes = context.document.meshes;
    context.model.meshes.resize(meshes.size());
    for (std::size_t m = 0; m < meshes.size(); ++m) {
        Mesh& mesh = context.model.meshes[m];
        mesh.name = meshes[m].name;
        mesh.defaultWeights =
            readMorphWeights(context, elementName("meshes", m), meshes[m].weights);
        for (std::size_t p = 0; p < meshes[m].primitives.size(); ++p) {
            const std::string element =
                elementName("meshes", m) + "." + elementName("primitives", p);
            if (isLineMode(meshes[m].primitives[p].mode)) {
                convertLines(context, meshes[m].primitives[p], element, mesh);
                continue;
            }
            if (auto primitive = convertPrimitive(context, meshes[m].primitives[p], element)) {
                mesh.primitives.push_back(std::move(*primitive));
            }
        }
        checkMorphTargetCounts(context, elementName("meshes", m), mesh);
    }
}

}  // namespace candela::content::gltf
