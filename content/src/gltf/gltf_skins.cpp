// glTF skins -> Model::skins, and each node's skin reference once its mesh is known to fit
// the skin (every JOINTS_n index below the joint count). A bad skin or a mesh whose joint
// indices overflow it leaves the node unskinned (bind pose) with an error naming both.
#include <algorithm>
#include <cmath>

#include "candela/content/animation_systems.h"
#include "gltf_accessors.h"
#include "gltf_context.h"
#include "gltf_value_limits.h"

namespace candela::content::gltf {
namespace {

constexpr Matrix4 kIdentity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

bool convertSkin(Context& context, const tinygltf::Skin& from, const std::string& element,
                 SkinData& skin) {
    skin.name = from.name;
    if (from.joints.empty()) {
        context.error(element, "has no joints; skin dropped");
        return false;
    }
    for (std::size_t j = 0; j < from.joints.size(); ++j) {
        if (!validIndex(from.joints[j], context.model.nodes)) {
            context.error(element, "joints[" + std::to_string(j) + "] is node " +
                                       std::to_string(from.joints[j]) +
                                       ", which does not exist; skin dropped");
            return false;
        }
        skin.joints.push_back(from.joints[j]);
    }
    if (from.skeleton >= 0 || from.skeleton < -1) {
        if (validIndex(from.skeleton, context.model.nodes))
            skin.skeleton = from.skeleton;
        else
            context.warning(element, "skeleton node " + std::to_string(from.skeleton) +
                                         " does not exist; ignored");
    }
    skin.inverseBindMatrices.assign(skin.joints.size(), kIdentity);
    if (from.inverseBindMatrices >= 0 || from.inverseBindMatrices < -1) {
        std::vector<float> flat;
        const AccessorLimits limits{context.options.maxElementsWithoutBufferView};
        std::string error =
            readFloats(context.document, from.inverseBindMatrices, 16, flat, limits);
        if (error.empty() && flat.size() < skin.joints.size() * 16)
            error = std::to_string(flat.size() / 16) + " matrices for " +
                    std::to_string(skin.joints.size()) + " joints";
        if (error.empty() && !allUsableMagnitudes(flat))
            error = "NaN/Inf values or values beyond 1e9";
        // A joint whose inverse bind matrix flattens space (all zero: determinant 0) collapses
        // every vertex it weighs onto a point.
        for (std::size_t j = 0; error.empty() && j < skin.joints.size(); ++j) {
            const float* m = flat.data() + j * 16;  // column-major
            const double det = double(m[0]) * (double(m[5]) * m[10] - double(m[9]) * m[6]) -
                               double(m[4]) * (double(m[1]) * m[10] - double(m[9]) * m[2]) +
                               double(m[8]) * (double(m[1]) * m[6] - double(m[5]) * m[2]);
            if (det == 0.0) error = "matrix " + std::to_string(j) + " is singular";
        }
        if (!error.empty()) {
            context.error(element, "inverseBindMatrices: " + error + "; skin dropped");
            return false;
        }
        for (std::size_t j = 0; j < skin.joints.size(); ++j)
            std::copy_n(flat.begin() + static_cast<std::ptrdiff_t>(j * 16), 16,
                        skin.inverseBindMatrices[j].begin());
    }
    return true;
}

}  // namespace

void convertSkins(Context& context) {
    Model& model = context.model;
    const auto& skins = context.document.skins;
    std::vector<bool> usable(skins.size(), false);
    model.skins.resize(skins.size());
    for (std::size_t s = 0; s < skins.size(); ++s)
        usable[s] = convertSkin(context, skins[s], elementName("skins", s), model.skins[s]);

    const auto& nodes = context.document.nodes;
    for (std::size_t n = 0; n < nodes.size(); ++n) {
        const int skin = nodes[n].skin;
        if (skin == -1) continue;
        const std::string element = elementName("nodes", n);
        if (!validIndex(skin, skins)) {
            context.error(element,
                          "skin " + std::to_string(skin) + " does not exist; shown in bind pose");
            continue;
        }
        if (!usable[static_cast<std::size_t>(skin)]) continue;  // already reported
        Node& node = model.nodes[n];
        if (node.mesh == kNoIndex) continue;  // a skin without a mesh deforms nothing
        const std::size_t jointCount = model.skins[static_cast<std::size_t>(skin)].joints.size();
        const Mesh& mesh = model.meshes[static_cast<std::size_t>(node.mesh)];
        bool fits = false;  // a mesh without JOINTS_n/WEIGHTS_n has nothing to skin
        for (const Primitive& primitive : mesh.primitives)
            fits = fits || !primitive.joints.empty();
        for (std::size_t p = 0; p < mesh.primitives.size() && fits; ++p) {
            for (std::size_t v = 0; v < mesh.primitives[p].joints.size() && fits; ++v) {
                for (std::uint16_t joint : mesh.primitives[p].joints[v]) {
                    if (joint >= jointCount) {
                        context.error(element, "mesh " + std::to_string(node.mesh) + " primitive " +
                                                   std::to_string(p) + " vertex " +
                                                   std::to_string(v) + " uses joint " +
                                                   std::to_string(joint) + " but skins[" +
                                                   std::to_string(skin) + "] has " +
                                                   std::to_string(jointCount) +
                                                   " joints; shown in bind pose");
                        fits = false;
                        break;
                    }
                }
            }
        }
        if (fits) node.skin = skin;
    }
    // Each skinned mesh's joint boxes, once for every instance (the skins read them each
    // frame: one copy for a crowd stays in cache).
    std::vector<std::size_t> jointCount(model.meshes.size(), 0);
    for (const Node& node : model.nodes)
        if (node.mesh != kNoIndex && node.skin != kNoIndex)
            jointCount[static_cast<std::size_t>(node.mesh)] =
                std::max(jointCount[static_cast<std::size_t>(node.mesh)],
                         model.skins[static_cast<std::size_t>(node.skin)].joints.size());
    for (std::size_t m = 0; m < model.meshes.size(); ++m)
        if (jointCount[m] > 0)
            model.meshes[m].jointBounds = jointBoundsOf(model.meshes[m], jointCount[m]);
}

}  // namespace candela::content::gltf
