// glTF nodes -> Model::nodes: names, TRS (matrices decomposed), validated references, and a
// hierarchy that is guaranteed to be a forest (one parent per node, no cycles).
#include <cmath>

#include "gltf_context.h"
#include "gltf_physics_extras.h"
#include "gltf_values.h"

namespace candela::content::gltf {
namespace {

using Float3x3 = std::array<Float3, 3>;  // columns

float dot(const Float3& a, const Float3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Float3 cross(const Float3& a, const Float3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Rotation matrix (orthonormal columns) -> unit quaternion (x, y, z, w).
Float4 quaternionFromRotation(const Float3x3& r) {
    const float m00 = r[0][0], m11 = r[1][1], m22 = r[2][2];
    const float trace = m00 + m11 + m22;
    Float4 q;
    if (trace > 0) {
        const float s = std::sqrt(trace + 1.0f) * 2;
        q = {(r[1][2] - r[2][1]) / s, (r[2][0] - r[0][2]) / s, (r[0][1] - r[1][0]) / s, 0.25f * s};
    } else if (m00 > m11 && m00 > m22) {
        const float s = std::sqrt(1.0f + m00 - m11 - m22) * 2;
        q = {0.25f * s, (r[1][0] + r[0][1]) / s, (r[2][0] + r[0][2]) / s, (r[1][2] - r[2][1]) / s};
    } else if (m11 > m22) {
        const float s = std::sqrt(1.0f + m11 - m00 - m22) * 2;
        q = {(r[1][0] + r[0][1]) / s, 0.25f * s, (r[2][1] + r[1][2]) / s, (r[2][0] - r[0][2]) / s};
    } else {
        const float s = std::sqrt(1.0f + m22 - m00 - m11) * 2;
        q = {(r[2][0] + r[0][2]) / s, (r[2][1] + r[1][2]) / s, 0.25f * s, (r[0][1] - r[1][0]) / s};
    }
    const float length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (float& c : q)
        c /= length;
    return q;
}

// Column-major glTF matrix -> TRS. Shear cannot be represented and is dropped with a warning.
Transform decomposeMatrix(Context& context, const std::string& element,
                          const std::array<float, 16>& m) {
    Transform t;
    t.translation = {m[12], m[13], m[14]};
    Float3x3 columns = {Float3{m[0], m[1], m[2]}, Float3{m[4], m[5], m[6]},
                        Float3{m[8], m[9], m[10]}};
    for (int c = 0; c < 3; ++c)
        t.scale[c] = std::sqrt(dot(columns[c], columns[c]));
    if (dot(columns[0], cross(columns[1], columns[2])) < 0) t.scale[0] = -t.scale[0];
    if (t.scale[0] == 0 || t.scale[1] == 0 || t.scale[2] == 0) return t;  // rotation unknowable
    for (int c = 0; c < 3; ++c) {
        for (float& v : columns[c])
            v /= t.scale[c];
    }
    const float shear = std::fabs(dot(columns[0], columns[1])) +
                        std::fabs(dot(columns[1], columns[2])) +
                        std::fabs(dot(columns[0], columns[2]));
    if (shear > 1e-3f) context.warning(element, "matrix has shear, which TRS cannot hold; dropped");
    if (m[3] != 0 || m[7] != 0 || m[11] != 0 || m[15] != 1) {
        context.warning(element, "matrix has a projective row; ignored");
    }
    t.rotation = quaternionFromRotation(columns);
    return t;
}

// Reads the node's transform. Returns false (and leaves identity) for NaN/Inf values.
bool readTransform(Context& context, const std::string& element, const tinygltf::Node& node,
                   Transform& transform) {
    if (!node.matrix.empty()) {
        std::array<float, 16> m{};
        if (!copyFactors(node.matrix, m)) return false;
        transform = decomposeMatrix(context, element, m);
    } else {
        if (!node.translation.empty() && !copyFactors(node.translation, transform.translation)) {
            return false;
        }
        if (!node.rotation.empty() && !copyFactors(node.rotation, transform.rotation)) return false;
        if (!node.scale.empty() && !copyFactors(node.scale, transform.scale)) return false;
    }
    Float4& q = transform.rotation;
    const float length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (!std::isfinite(length)) return false;
    if (length < 1e-6f) {
        context.warning(element, "rotation is a zero quaternion; using identity");
        q = {0, 0, 0, 1};
    } else if (std::fabs(length - 1.0f) > 1e-3f) {
        context.warning(element, "rotation is not a unit quaternion; normalised");
        for (float& c : q)
            c /= length;
    } else {
        for (float& c : q)
            c /= length;
    }
    return true;
}

std::int32_t lightIndexOf(const tinygltf::Node& node) {
    auto it = node.extensions.find("KHR_lights_punctual");
    if (it == node.extensions.end()) return kNoIndex;
    float index = -1;
    if (!readNumber(it->second, "light", index) || index < 0 || index > 1e9f) return -2;
    return static_cast<std::int32_t>(index);
}

// Parents from children lists: drops self-references, second parents and cycles, so every
// later traversal can assume a forest.
void buildHierarchy(Context& context) {
    std::vector<Node>& nodes = context.model.nodes;
    const auto& source = context.document.nodes;
    for (std::size_t n = 0; n < source.size(); ++n) {
        const std::string element = elementName("nodes", n);
        for (int child : source[n].children) {
            if (!validIndex(child, nodes) || static_cast<std::size_t>(child) == n) {
                context.error(element, "child " + std::to_string(child) +
                                           " is not another existing node; ignored");
                continue;
            }
            Node& c = nodes[static_cast<std::size_t>(child)];
            if (c.parent != kNoIndex) {
                context.error(element, "child " + std::to_string(child) + " already has parent " +
                                           std::to_string(c.parent) + "; ignored");
                continue;
            }
            c.parent = static_cast<std::int32_t>(n);
        }
    }
    // Cycle removal, linear time: walk up from each node, marking the walk; meeting a node of
    // the current walk means a cycle, broken at the node we started from.
    std::vector<std::int32_t> walkOf(nodes.size(), -1);
    std::vector<bool> done(nodes.size(), false);
    for (std::size_t start = 0; start < nodes.size(); ++start) {
        std::int32_t at = static_cast<std::int32_t>(start);
        while (at != kNoIndex && !done[static_cast<std::size_t>(at)]) {
            const auto i = static_cast<std::size_t>(at);
            if (walkOf[i] == static_cast<std::int32_t>(start)) {
                context.error(elementName("nodes", i),
                              "is part of a parent cycle; detached from parent " +
                                  std::to_string(nodes[i].parent));
                nodes[i].parent = kNoIndex;
                break;
            }
            walkOf[i] = static_cast<std::int32_t>(start);
            at = nodes[i].parent;
        }
        for (at = static_cast<std::int32_t>(start);
             at != kNoIndex && !done[static_cast<std::size_t>(at)];
             at = nodes[static_cast<std::size_t>(at)].parent) {
            done[static_cast<std::size_t>(at)] = true;
        }
    }
    for (std::size_t n = 0; n < nodes.size(); ++n) {
        if (nodes[n].parent != kNoIndex) {
            nodes[static_cast<std::size_t>(nodes[n].parent)].children.push_back(
                static_cast<std::int32_t>(n));
        }
    }
}

void chooseRoots(Context& context) {
    const tinygltf::Model& document = context.document;
    Model& model = context.model;
    std::vector<bool> isRoot(model.nodes.size(), false);
    auto addRoot = [&](int node, const std::string& element) {
        if (!validIndex(node, model.nodes)) {
            context.error(element, "root node " + std::to_string(node) + " does not exist");
        } else if (model.nodes[static_cast<std::size_t>(node)].parent != kNoIndex) {
            context.error(element, "root node " + std::to_string(node) + " has a parent; ignored");
        } else if (!isRoot[static_cast<std::size_t>(node)]) {
            isRoot[static_cast<std::size_t>(node)] = true;
            model.rootNodes.push_back(node);
        }
    };
    if (document.scenes.empty()) {
        for (std::size_t n = 0; n < model.nodes.size(); ++n) {
            if (model.nodes[n].parent == kNoIndex) addRoot(static_cast<int>(n), "");
        }
        return;
    }
    int scene = document.defaultScene;
    if (!validIndex(scene, document.scenes)) {
        if (scene != -1)
            context.error("scene", "scene " + std::to_string(scene) + " does not exist; using 0");
        scene = 0;
    }
    const std::string element = elementName("scenes", static_cast<std::size_t>(scene));
    for (int node : document.scenes[static_cast<std::size_t>(scene)].nodes)
        addRoot(node, element);
}

}  // namespace

void convertNodes(Context& context) {
    const auto& source = context.document.nodes;
    Model& model = context.model;
    model.nodes.resize(source.size());
    for (std::size_t n = 0; n < source.size(); ++n) {
        const tinygltf::Node& from = source[n];
        Node& node = model.nodes[n];
        const std::string element = elementName("nodes", n);
        node.name = from.name;
        if (!readTransform(context, element, from, node.local)) {
            context.error(element, "transform has NaN/Inf or malformed values; using identity");
            node.local = Transform{};
        }
        if (from.mesh >= 0 || from.mesh < -1) {
            if (validIndex(from.mesh, model.meshes))
                node.mesh = from.mesh;
            else
                context.error(element, "mesh " + std::to_string(from.mesh) + " does not exist");
        }
        if (from.camera >= 0 || from.camera < -1) {
            if (validIndex(from.camera, model.cameras))
                node.camera = from.camera;
            else
                context.error(element, "camera " + std::to_string(from.camera) + " does not exist");
        }
        if (const std::int32_t light = lightIndexOf(from); light != kNoIndex) {
            if (validIndex(light, model.lights))
                node.light = light;
            else
                context.error(element, "KHR_lights_punctual light " + std::to_string(light) +
                                           " does not exist");
        }
        node.weights = readMorphWeights(context, element, from.weights);
        PhysicsExtras physics =
            readPhysicsExtras(from.extras_json_string, context.file, element, context.diagnostics);
        node.rigidBody = physics.rigidBody;
        node.collider = physics.collider;
    }
    buildHierarchy(context);
    chooseRoots(context);
}

}  // namespace candela::content::gltf
