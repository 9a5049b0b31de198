// glTF animations -> Model::animations. A clip with any bad element (missing node or sampler,
// NaN keys, key times not increasing, output count not matching input) is dropped whole, with
// an error naming the file and the element; the rest of the model loads unchanged.
#include <algorithm>
#include <cmath>

#include "candela/content/animation_sampling.h"
#include "gltf_accessors.h"
#include "gltf_context.h"
#include "gltf_value_limits.h"

namespace candela::content::gltf {
namespace {

bool parseProperty(const std::string& path, AnimatedProperty& out) {
    if (path == "translation")
        out = AnimatedProperty::Translation;
    else if (path == "rotation")
        out = AnimatedProperty::Rotation;
    else if (path == "scale")
        out = AnimatedProperty::Scale;
    else if (path == "weights")
        out = AnimatedProperty::Weights;
    else
        return false;
    return true;
}

bool parseInterpolation(const std::string& name, Interpolation& out) {
    if (name == "STEP")
        out = Interpolation::Step;
    else if (name == "LINEAR" || name.empty())
        out = Interpolation::Linear;
    else if (name == "CUBICSPLINE")
        out = Interpolation::CubicSpline;
    else
        return false;
    return true;
}

std::uint32_t morphTargetCount(const Model& model, std::int32_t node) {
    const std::int32_t mesh = model.nodes[static_cast<std::size_t>(node)].mesh;
    if (mesh == kNoIndex) return 0;
    return static_cast<std::uint32_t>(
        model.meshes[static_cast<std::size_t>(mesh)].defaultWeights.size());
}

// Reads and checks one sampler; `components` comes from the channel that uses it.
std::string convertSampler(Context& context, const tinygltf::AnimationSampler& from,
                           std::uint32_t components, AnimationSampler& out) {
    if (!parseInterpolation(from.interpolation, out.interpolation))
        return "interpolation '" + from.interpolation + "' is not STEP, LINEAR or CUBICSPLINE";
    out.components = components;
    const AccessorLimits limits{context.options.maxElementsWithoutBufferView};
    if (std::string error = readFloats(context.document, from.input, 1, out.times, limits);
        !error.empty())
        return "input: " + error;
    if (out.times.empty()) return "input has no keys";
    for (std::size_t k = 0; k < out.times.size(); ++k) {
        if (!std::isfinite(out.times[k])) return "input key " + std::to_string(k) + " is NaN/Inf";
        if (k > 0 && !(out.times[k] > out.times[k - 1]))
            return "input key times are not increasing at key " + std::to_string(k) + " (" +
                   std::to_string(out.times[k - 1]) + " then " + std::to_string(out.times[k]) + ")";
    }
    // Output element types differ (VEC3, VEC4, SCALAR for weights): read as scalars.
    std::uint64_t outputCount = 0;
    if (std::string error = accessorCount(context.document, from.output, outputCount);
        !error.empty())
        return "output: " + error;
    const tinygltf::Accessor& accessor =
        context.document.accessors[static_cast<std::size_t>(from.output)];
    const std::uint32_t perElement = componentCount(accessor.type);
    if (perElement == 0) return "output has an unknown type";
    if (std::string error =
            readFloats(context.document, from.output, perElement, out.values, limits);
        !error.empty())
        return "output: " + error;
    const std::uint64_t perKey =
        std::uint64_t{components} * (out.interpolation == Interpolation::CubicSpline ? 3 : 1);
    const std::uint64_t expected = perKey * out.times.size();
    if (out.values.size() != expected)
        return "output has " + std::to_string(out.values.size()) + " values but " +
               std::to_string(out.times.size()) + " input keys need " + std::to_string(expected);
    for (std::size_t i = 0; i < out.values.size(); ++i) {
        if (!usableMagnitude(out.values[i]))
            return "output key " + std::to_string(i / perKey) +
                   " has a NaN/Inf value or one beyond 1e9";
    }
    return {};
}

bool convertClip(Context& context, const tinygltf::Animation& from, const std::string& element,
                 AnimationClip& clip) {
    const Model& model = context.model;
    clip.name = from.name;
    clip.samplers.resize(from.samplers.size());
    std::vector<bool> converted(from.samplers.size(), false);
    for (std::size_t c = 0; c < from.channels.size(); ++c) {
        const tinygltf::AnimationChannel& channel = from.channels[c];
        const std::string channelElement = element + "." + elementName("channels", c);
        AnimationChannel out;
        if (!parseProperty(channel.target_path, out.property)) {
            context.error(channelElement, "target path '" + channel.target_path +
                                              "' is not translation, rotation, scale or "
                                              "weights; animation dropped");
            return false;
        }
        if (!validIndex(channel.target_node, model.nodes)) {
            context.error(channelElement, "targets node " + std::to_string(channel.target_node) +
                                              ", which does not exist; animation dropped");
            return false;
        }
        if (!validIndex(channel.sampler, from.samplers)) {
            context.error(channelElement, "sampler " + std::to_string(channel.sampler) +
                                              " does not exist; animation dropped");
            return false;
        }
        out.node = channel.target_node;
        out.sampler = channel.sampler;
        std::uint32_t components = out.property == AnimatedProperty::Rotation ? 4 : 3;
        if (out.property == AnimatedProperty::Weights) {
            components = morphTargetCount(model, out.node);
            if (components == 0) {
                context.error(channelElement, "animates weights of node " +
                                                  std::to_string(out.node) +
                                                  ", which has no morph targets; animation "
                                                  "dropped");
                return false;
            }
        }
        const auto s = static_cast<std::size_t>(out.sampler);
        if (converted[s]) {
            if (clip.samplers[s].components != components) {
                context.error(channelElement, "shares sampler " + std::to_string(s) +
                                                  " with a channel of another value size; "
                                                  "animation dropped");
                return false;
            }
        } else {
            const std::string samplerElement = element + "." + elementName("samplers", s);
            if (std::string error =
                    convertSampler(context, from.samplers[s], components, clip.samplers[s]);
                !error.empty()) {
                context.error(samplerElement, error + "; animation dropped");
                return false;
            }
            converted[s] = true;
        }
        clip.channels.push_back(out);
    }
    for (const AnimationSampler& sampler : clip.samplers) {
        if (!sampler.times.empty()) clip.duration = std::max(clip.duration, sampler.times.back());
    }
    for (const AnimationChannel& channel : clip.channels) {
        if (channel.property == AnimatedProperty::Rotation)
            prepareSlerpAngles(clip.samplers[static_cast<std::size_t>(channel.sampler)]);
    }
    markSharedKeyTimes(clip);
    return true;
}

}  // namespace

void convertAnimations(Context& context) {
    const auto& animations = context.document.animations;
    for (std::size_t a = 0; a < animations.size(); ++a) {
        AnimationClip clip;
        if (convertClip(context, animations[a], elementName("animations", a), clip))
            context.model.animations.push_back(std::move(clip));
    }
}

}  // namespace candela::content::gltf
