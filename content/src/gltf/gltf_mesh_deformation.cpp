// Per-vertex skinning influences (JOINTS_n/WEIGHTS_n) and morph targets of a glTF primitive.
// Broken data drops only the deformation (the primitive shows its bind pose / base shape),
// with an error naming the primitive and the attribute.
#include <algorithm>
#include <cmath>

#include "gltf_accessors.h"
#include "gltf_context.h"
#include "gltf_value_limits.h"

namespace candela::content::gltf {
namespace {

constexpr std::uint32_t kMaxInfluenceSets = 8;  // JOINTS_0..7: 32 influences per vertex

struct Influence {
    float weight;
    std::uint32_t joint;
};

bool readSet(Context& context, const std::string& element, const tinygltf::Primitive& source,
             const std::string& name, std::size_t vertexCount, const AccessorLimits& limits,
             std::vector<float>& out) {
    const auto it = source.attributes.find(name);
    if (it == source.attributes.end()) return false;
    if (std::string error = readFloats(context.document, it->second, 4, out, limits);
        !error.empty()) {
        context.error(element, name + ": " + error + "; skinning dropped (bind pose)");
        return false;
    }
    if (out.size() != vertexCount * 4) {
        context.error(element, name + " has " + std::to_string(out.size() / 4) +
                                   " elements but POSITION has " + std::to_string(vertexCount) +
                                   "; skinning dropped (bind pose)");
        return false;
    }
    return true;
}

}  // namespace

void readSkinAttributes(Context& context, const std::string& element,
                        const tinygltf::Primitive& source, std::size_t vertexCount,
                        const AccessorLimits& limits, Primitive& primitive) {
    std::vector<std::vector<float>> jointSets;
    std::vector<std::vector<float>> weightSets;
    for (std::uint32_t set = 0; set < kMaxInfluenceSets; ++set) {
        const std::string jointsName = "JOINTS_" + std::to_string(set);
        const std::string weightsName = "WEIGHTS_" + std::to_string(set);
        const bool hasJoints = source.attributes.count(jointsName) != 0;
        const bool hasWeights = source.attributes.count(weightsName) != 0;
        if (!hasJoints && !hasWeights) break;
        if (hasJoints != hasWeights) {
            context.error(element, (hasJoints ? jointsName + " has no " + weightsName
                                              : weightsName + " has no " + jointsName) +
                                       "; skinning dropped (bind pose)");
            return;
        }
        std::vector<float> joints;
        std::vector<float> weights;
        if (!readSet(context, element, source, jointsName, vertexCount, limits, joints) ||
            !readSet(context, element, source, weightsName, vertexCount, limits, weights)) {
            return;
        }
        for (std::size_t i = 0; i < joints.size(); ++i) {
            const float j = joints[i];
            if (!(j >= 0 && j <= 65535 && j == std::floor(j))) {
                context.error(element, jointsName + " vertex " + std::to_string(i / 4) +
                                           " has joint index " + std::to_string(j) +
                                           ", not an integer in [0, 65535]; skinning dropped "
                                           "(bind pose)");
                return;
            }
            if (!std::isfinite(weights[i]) || weights[i] < 0) {
                context.error(element, weightsName + " vertex " + std::to_string(i / 4) +
                                           " has weight " + std::to_string(weights[i]) +
                                           " (negative or NaN); skinning dropped (bind pose)");
                return;
            }
        }
        jointSets.push_back(std::move(joints));
        weightSets.push_back(std::move(weights));
    }
    if (jointSets.empty()) return;

    // Keep the four largest influences and renormalise: the GPU path reads one uvec4/vec4
    // pair per vertex (Filament and Bevy do the same).
    std::vector<JointIndices> joints(vertexCount);
    std::vector<Float4> weights(vertexCount);
    std::vector<Influence> influences;
    influences.reserve(jointSets.size() * 4);
    for (std::size_t v = 0; v < vertexCount; ++v) {
        influences.clear();
        for (std::size_t s = 0; s < jointSets.size(); ++s) {
            for (std::size_t c = 0; c < 4; ++c) {
                const float w = weightSets[s][v * 4 + c];
                if (w > 0)
                    influences.push_back({w, static_cast<std::uint32_t>(jointSets[s][v * 4 + c])});
            }
        }
        if (influences.empty()) {
            context.error(element, "WEIGHTS_n of vertex " + std::to_string(v) +
                                       " are all zero; skinning dropped (bind pose)");
            return;
        }
        std::partial_sort(
            influences.begin(),
            influences.begin() +
                static_cast<std::ptrdiff_t>(std::min<std::size_t>(4, influences.size())),
            influences.end(),
            [](const Influence& a, const Influence& b) { return a.weight > b.weight; });
        // In double: four weights of 3e38 sum to Inf in float and normalised to zero.
        double sum = 0;
        for (std::size_t c = 0; c < 4 && c < influences.size(); ++c)
            sum += influences[c].weight;
        for (std::size_t c = 0; c < 4; ++c) {
            const bool used = c < influences.size();
            joints[v][c] = used ? static_cast<std::uint16_t>(influences[c].joint) : 0;
            weights[v][c] = used ? float(influences[c].weight / sum) : 0.0f;
        }
    }
    primitive.joints = std::move(joints);
    primitive.weights = std::move(weights);
}

void readMorphTargets(Context& context, const std::string& element,
                      const tinygltf::Primitive& source, std::size_t vertexCount,
                      const AccessorLimits& limits, Primitive& primitive) {
    std::vector<MorphTarget> targets(source.targets.size());
    for (std::size_t t = 0; t < source.targets.size(); ++t) {
        const std::string targetElement = element + "." + elementName("targets", t);
        for (const auto& [name, accessor] : source.targets[t]) {
            std::vector<Float3>* out = name == "POSITION"  ? &targets[t].positionDeltas
                                       : name == "NORMAL"  ? &targets[t].normalDeltas
                                       : name == "TANGENT" ? &targets[t].tangentDeltas
                                                           : nullptr;
            if (out == nullptr) continue;  // TEXCOORD/COLOR targets: not supported, ignored
            std::vector<float> flat;
            std::string error = readFloats(context.document, accessor, 3, flat, limits);
            if (error.empty() && flat.size() != vertexCount * 3)
                error = std::to_string(flat.size() / 3) + " elements but POSITION has " +
                        std::to_string(vertexCount);
            if (error.empty() && !allUsableMagnitudes(flat))
                error = "NaN/Inf values or values beyond 1e9";
            if (!error.empty()) {
                context.error(targetElement, name + ": " + error + "; morph targets dropped");
                return;
            }
            out->resize(vertexCount);
            for (std::size_t v = 0; v < vertexCount; ++v)
                (*out)[v] = {flat[v * 3], flat[v * 3 + 1], flat[v * 3 + 2]};
        }
    }
    primitive.morphTargets = std::move(targets);
}

std::vector<float> readMorphWeights(Context& context, const std::string& element,
                                    const std::vector<double>& weights) {
    std::vector<float> out;
    out.reserve(weights.size());
    for (std::size_t w = 0; w < weights.size(); ++w) {
        const float weight = static_cast<float>(weights[w]);
        if (!usableMagnitude(weight)) {
            context.warning(element,
                            "weights[" + std::to_string(w) + "] is NaN/Inf or beyond 1e9; 0 used");
        }
        out.push_back(usableMagnitude(weight) ? weight : 0.0f);
    }
    return out;
}

}  // namespace candela::content::gltf
