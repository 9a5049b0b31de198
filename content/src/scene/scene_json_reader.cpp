// JSON text -> SceneDocument. Structure errors name the file and the JSON pointer; a
// malformed component is dropped (the entity stays), a malformed file yields nullopt.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <type_traits>
#include <utility>
#include <vector>

#include "candela/content/builtin_meshes.h"
#include "candela/content/component_validation.h"
#include "candela/content/light_texture.h"
#include "candela/content/render_setting_table.h"
#include "candela/content/scene_file.h"
#include "candela/ecs/rotation.h"
#include "scene_json_names.h"

namespace candela::content {
namespace {

using nlohmann::json;
using namespace scene;

// Nesting depth, measured without recursion (game data is free-form and could be deep
// enough to overflow the stack of a recursive walk, including json::dump()).
std::size_t nestingDepth(const json& root) {
    std::size_t deepest = 0;
    std::vector<std::pair<const json*, std::size_t>> stack{{&root, 1}};
    while (!stack.empty()) {
        auto [node, depth] = stack.back();
        stack.pop_back();
        deepest = std::max(deepest, depth);
        if (node->is_structured()) {
            for (const json& child : *node)
                stack.push_back({&child, depth + 1});
        }
    }
    return deepest;
}

class Reader {
public:
    Reader(const std::string& file, Diagnostics& diagnostics)
        : file_(file), diagnostics_(diagnostics) {}

    void error(const std::string& pointer, const std::string& message) {
        diagnostics_.error(file_, pointer, message);
        errorPointers_.push_back(pointer);
        failed_ = true;
    }

    // Keys the reading looked for, per JSON object (whether present or not), so the keys it
    // never looked for can be named (reportUnknownKeys): a typo such as "translaton" loaded as
    // if absent, without a word (issue 44).
    void known(const json& object, const std::string& p, const char* key) {
        KnownKeys& k = known_[&object];
        k.pointer = p;
        k.keys.insert(key);
    }
    bool has(const json& object, const std::string& p, const char* key) {
        known(object, p, key);
        return object.contains(key);
    }
    // A warning per key of a read object that no reading looked for, with the closest known
    // key when one is near. Objects with an error of their own (at the object or one of its
    // keys) are left out: their reading may have stopped before it looked for the rest.
    void reportUnknownKeys() {
        auto ownError = [](const std::string& error, const std::string& object) {
            if (error == object) return true;
            const std::string prefix = object + "/";
            return error.rfind(prefix, 0) == 0 &&
                   error.find('/', prefix.size()) == std::string::npos;
        };
        std::vector<std::pair<std::string, std::string>> unknown;
        for (const auto& [object, k] : known_) {
            if (!object->is_object()) continue;
            // A named copy: clang 14 cannot capture a structured binding in a lambda.
            const std::string& objectPointer = k.pointer;
            if (std::any_of(errorPointers_.begin(), errorPointers_.end(),
                            [&](const std::string& e) { return ownError(e, objectPointer); })) {
                continue;
            }
            for (const auto& item : object->items()) {
                if (k.keys.count(item.key())) continue;
                const std::string shown =
                    item.key().size() > 64 ? item.key().substr(0, 64) + "..." : item.key();
                std::string message = "unknown key '" + shown + "', ignored";
                if (const std::string near = closestKey(item.key(), k.keys); !near.empty()) {
                    message += " (did you mean '" + near + "'?)";
                }
                unknown.emplace_back(k.pointer + "/" + shown, std::move(message));
            }
        }
        // Sorted by pointer, so the order is the same run after run (not the objects' addresses).
        std::sort(unknown.begin(), unknown.end());
        for (const auto& [pointer, message] : unknown)
            warning(pointer, message);
    }
    void warning(const std::string& pointer, const std::string& message) {
        diagnostics_.warning(file_, pointer, message);
    }

    // Each read leaves `out` unchanged when the key is absent and records an error (setting
    // failed_) when it is present but wrong.
    void number(const json& object, const std::string& p, const char* key, float& out) {
        known(object, p, key);
        auto it = object.find(key);
        if (it == object.end()) return;
        if (!it->is_number()) return error(p + "/" + key, "expected a number");
        const double v = it->get<double>();
        if (!std::isfinite(v) || std::fabs(v) > std::numeric_limits<float>::max()) {
            return error(p + "/" + key, "number out of float range");
        }
        out = static_cast<float>(v);
    }
    template <std::size_t N>
    void numbers(const json& object, const std::string& p, const char* key,
                 std::array<float, N>& out) {
        known(object, p, key);
        auto it = object.find(key);
        if (it == object.end()) return;
        if (!it->is_array() || it->size() != N) {
            return error(p + "/" + key, "expected an array of " + std::to_string(N) + " numbers");
        }
        std::array<float, N> values{};
        for (std::size_t i = 0; i < N; ++i) {
            const json& e = (*it)[i];
            if (!e.is_number() || !std::isfinite(e.get<double>()) ||
                std::fabs(e.get<double>()) > std::numeric_limits<float>::max()) {
                return error(p + "/" + key + "/" + std::to_string(i), "expected a finite number");
            }
            values[i] = static_cast<float>(e.get<double>());
        }
        out = values;
    }
    template <typename Int>
    void integer(const json& object, const std::string& p, const char* key, Int& out,
                 std::int64_t lo, std::int64_t hi) {
        known(object, p, key);
        auto it = object.find(key);
        if (it == object.end()) return;
        if (!it->is_number_integer()) return error(p + "/" + key, "expected an integer");
        const auto v = it->get<std::int64_t>();
        if (v < lo || v > hi ||
            (it->is_number_unsigned() && it->get<std::uint64_t>() > std::uint64_t(hi))) {
            return error(p + "/" + key, "integer out of range [" + std::to_string(lo) + ", " +
                                            std::to_string(hi) + "]");
        }
        out = static_cast<Int>(v);
    }
    void string(const json& object, const std::string& p, const char* key, std::string& out) {
        known(object, p, key);
        auto it = object.find(key);
        if (it == object.end()) return;
        if (!it->is_string()) return error(p + "/" + key, "expected a string");
        out = it->get<std::string>();
    }
    void boolean(const json& object, const std::string& p, const char* key, bool& out) {
        known(object, p, key);
        auto it = object.find(key);
        if (it == object.end()) return;
        if (!it->is_boolean()) return error(p + "/" + key, "expected true or false");
        out = it->get<bool>();
    }
    template <typename E, std::size_t N>
    void enumeration(const json& object, const std::string& p, const char* key,
                     const EnumNames<E, N>& names, E& out) {
        known(object, p, key);
        std::string text;
        auto it = object.find(key);
        if (it == object.end()) return;
        string(object, p, key, text);
        for (const auto& [value, name] : names) {
            if (name == text) {
                out = value;
                return;
            }
        }
        std::string allowed;
        for (const auto& entry : names)
            allowed += (allowed.empty() ? "" : ", ") + std::string(entry.second);
        error(p + "/" + key, "'" + text + "' is not one of: " + allowed);
    }
    // "hair": fur grown on the entity's mesh (components/hair_growth.h). Radii and exponents
    // must be above 0, the colour in [0, 1], the count 1 to 1,000,000 and the length above 0.
    void hair(const json& h, const std::string& p, bool hasMesh, HairGrowth& out) {
        if (!hasMesh) return error(p, "hair grows on a mesh: the entity needs a \"mesh\"");
        integer(h, p, "count", out.count, 1, 1000000);
        number(h, p, "length", out.length);
        integer(h, p, "seed", out.seed, 0, std::numeric_limits<std::uint32_t>::max());
        if (!(out.length > 0.0f)) error(p + "/length", "a hair length must be above 0 metres");
        const json* s = nullptr;
        if (!object(h, p, "style", s)) return;
        const std::string q = p + "/style";
        HairStyle& style = out.style;
        number(*s, q, "rootRadius", style.rootRadius);
        style.tipRadius = style.rootRadius;  // not given: the strand keeps its width
        number(*s, q, "tipRadius", style.tipRadius);
        numbers(*s, q, "color", style.color);
        number(*s, q, "primaryShift", style.primaryShift);
        number(*s, q, "secondaryShift", style.secondaryShift);
        number(*s, q, "primaryExponent", style.primaryExponent);
        number(*s, q, "secondaryExponent", style.secondaryExponent);
        if (!(style.rootRadius > 0.0f)) error(q + "/rootRadius", "a radius must be above 0");
        if (!(style.tipRadius > 0.0f)) error(q + "/tipRadius", "a radius must be above 0");
        for (float c : style.color) {
            if (c < 0.0f || c > 1.0f) error(q + "/color", "a hair colour must be in [0, 1]");
        }
        if (!(style.primaryExponent > 0.0f))
            error(q + "/primaryExponent", "an exponent must be above 0");
        if (!(style.secondaryExponent > 0.0f))
            error(q + "/secondaryExponent", "an exponent must be above 0");
    }
    // A render setting's value under its row's key ("ssr", or "ambient_occlusion/mode" inside
    // an object another reading checks): a value name (a switch also as true or false), or a
    // number in the row's range. Unset when absent; reported and unset when wrong.
    template <typename T>
    void renderSetting(const json& root, const RenderSettingRow<T>& row, std::optional<T>& out) {
        const SceneKeyPath path = sceneKeyPath(row.sceneKey);
        const json* object = &root;
        std::string p;
        const std::string key(path.member);
        if (!path.object.empty()) {
            auto parent = root.find(path.object);
            if (parent == root.end() || !parent->is_object()) return;
            object = &*parent;
            p = "/" + std::string(path.object);
        }
        known(*object, p, key.c_str());
        auto it = object->find(key);
        if (it == object->end()) return;
        const std::string pointer = p + "/" + key;
        std::optional<T> value;
        if (!row.names.empty()) {
            if (it->is_string()) {
                value = parseRenderSetting(row, it->get<std::string>());
            } else if constexpr (std::is_same_v<T, bool>) {
                if (it->is_boolean()) value = it->get<bool>();
            }
        } else if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) {
            // The range first, so the conversion below is defined (NaN fails it too).
            const double number = it->is_number() ? it->get<double>() : std::nan("");
            if (number >= double(row.least) && number <= double(row.most)) {
                const T candidate = static_cast<T>(number);
                const bool exact = std::is_floating_point_v<T> || double(candidate) == number;
                if (exact && renderSettingAllows(row, candidate)) value = candidate;
            }
        }
        if (!value) {
            return error(pointer, "expected " + renderSettingExpects(row) + ", got " + it->dump());
        }
        out = value;
    }
    bool object(const json& parent, const std::string& p, const char* key, const json*& out) {
        known(parent, p, key);
        auto it = parent.find(key);
        if (it == parent.end()) return false;
        if (!it->is_object()) {
            error(p + "/" + key, "expected an object");
            return false;
        }
        out = &*it;
        return true;
    }

    // The shared component rules (component_validation.h): rejections are errors that drop
    // the component, clamps are warnings.
    void report(const std::string& p, const ValueProblems& problems) {
        for (const ValueProblem& problem : problems) {
            if (problem.clamped) {
                warning(p + "/" + problem.field, problem.message);
            } else {
                error(p + "/" + problem.field, problem.message);
            }
        }
    }

    // Runs `read` and reports whether it recorded no error, restoring the failure flag so
    // one bad component does not mark the next one bad.
    template <typename F>
    bool clean(F&& read) {
        const bool before = failed_;
        failed_ = false;
        read();
        const bool ok = !failed_;
        failed_ = before || failed_;
        return ok;
    }

    void transform(const json& j, const std::string& p, Transform& t) {
        numbers(j, p, "translation", t.translation);
        numbers(j, p, "rotation", t.rotation);
        numbers(j, p, "scale", t.scale);
        report(p, validateRotation(t.rotation));
        if (has(j, p, "lookAt")) {
            if (j.contains("rotation")) {
                return error(p + "/lookAt", "give \"rotation\" or \"lookAt\", not both");
            }
            std::array<float, 3> target{};
            if (!clean([&] { numbers(j, p, "lookAt", target); })) return;
            const std::optional<ecs::Quat> facing =
                ecs::lookAtRotation({t.translation[0], t.translation[1], t.translation[2]},
                                    {target[0], target[1], target[2]});
            if (facing) {
                t.rotation = {facing->x, facing->y, facing->z, facing->w};
            } else {
                error(p + "/lookAt", "the target is the entity's own position");
            }
        }
    }

    void textureRef(const json& parent, const std::string& p, const char* key, TextureRef& t) {
        const json* j = nullptr;
        if (!object(parent, p, key, j)) return;
        const std::string q = p + "/" + key;
        integer(*j, q, "texture", t.texture, -1, std::numeric_limits<std::int32_t>::max());
        integer(*j, q, "texCoord", t.texCoord, 0, 1);
        enumeration(*j, q, "colorSpace", kColorSpaces, t.colorSpace);
        numbers(*j, q, "offset", t.transform.offset);
        number(*j, q, "rotation", t.transform.rotation);
        numbers(*j, q, "scale", t.transform.scale);
    }

    void material(const json& j, const std::string& p, Material& m) {
        string(j, p, "name", m.name);
        enumeration(j, p, "shadingModel", kShadingModels, m.shadingModel);
        numbers(j, p, "baseColorFactor", m.baseColorFactor);
        textureRef(j, p, "baseColorTexture", m.baseColorTexture);
        number(j, p, "metallicFactor", m.metallicFactor);
        number(j, p, "roughnessFactor", m.roughnessFactor);
        textureRef(j, p, "metallicRoughnessTexture", m.metallicRoughnessTexture);
        textureRef(j, p, "normalTexture", m.normalTexture);
        number(j, p, "normalScale", m.normalScale);
        textureRef(j, p, "occlusionTexture", m.occlusionTexture);
        number(j, p, "occlusionStrength", m.occlusionStrength);
        number(j, p, "cavity", m.cavity);
        textureRef(j, p, "emissiveTexture", m.emissiveTexture);
        numbers(j, p, "emissiveFactor", m.emissiveFactor);
        number(j, p, "emissiveStrength", m.emissiveStrength);
        enumeration(j, p, "alphaMode", kAlphaModes, m.alphaMode);
        number(j, p, "alphaCutoff", m.alphaCutoff);
        boolean(j, p, "doubleSided", m.doubleSided);
        number(j, p, "specular", m.specular);
        textureRef(j, p, "specularTexture", m.specularTexture);
        textureRef(j, p, "specularColorTexture", m.specularColorTexture);
        numbers(j, p, "specularColorFactor", m.specularColorFactor);
        numbers(j, p, "subsurfaceColor", m.subsurfaceColor);
        number(j, p, "subsurfaceOpacity", m.subsurfaceOpacity);
        numbers(j, p, "diffuseColor", m.diffuseColor);
        numbers(j, p, "specularColor", m.specularColor);
        number(j, p, "anisotropyStrength", m.anisotropyStrength);
        number(j, p, "anisotropyRotation", m.anisotropyRotation);
        textureRef(j, p, "anisotropyTexture", m.anisotropyTexture);
        number(j, p, "clearcoatFactor", m.clearcoatFactor);
        textureRef(j, p, "clearcoatTexture", m.clearcoatTexture);
        number(j, p, "clearcoatRoughnessFactor", m.clearcoatRoughnessFactor);
        textureRef(j, p, "clearcoatRoughnessTexture", m.clearcoatRoughnessTexture);
        textureRef(j, p, "clearcoatNormalTexture", m.clearcoatNormalTexture);
        number(j, p, "clearcoatNormalScale", m.clearcoatNormalScale);
        report(p, validateMaterialFactors(m));
        report(p, validateEmission(m));
        if (has(j, p, "layers") || has(j, p, "layerMask")) layering(j, p, m);
    }

    // One layer's parameters (library entry or a material's copy of one).
    void layerParameters(const json& j, const std::string& p, MaterialLayer& l) {
        numbers(j, p, "baseColorFactor", l.baseColorFactor);
        number(j, p, "metallicFactor", l.metallicFactor);
        number(j, p, "roughnessFactor", l.roughnessFactor);
        number(j, p, "specular", l.specular);
        number(j, p, "normalScale", l.normalScale);
        textureRef(j, p, "baseColorTexture", l.baseColorTexture);
        textureRef(j, p, "metallicRoughnessTexture", l.metallicRoughnessTexture);
        textureRef(j, p, "normalTexture", l.normalTexture);
        numbers(j, p, "uvScale", l.uvScale);
        if (!(l.uvScale[0] > 0.0f && l.uvScale[1] > 0.0f)) {
            error(p + "/uvScale", "layer '" + l.name + "': UV scale must be greater than 0");
        }
    }

    // The layer library (top-level "materialLayers"); read before the entities.
    void layerLibrary(const json& root, std::vector<MaterialLayer>& library) {
        known(root, "", "materialLayers");
        auto it = root.find("materialLayers");
        if (it == root.end()) return;
        if (!it->is_array()) return error("/materialLayers", "expected an array");
        for (std::size_t i = 0; i < it->size(); ++i) {
            const std::string p = "/materialLayers/" + std::to_string(i);
            const json& j = (*it)[i];
            MaterialLayer layer;
            if (!clean([&] {
                    if (!j.is_object()) return error(p, "expected an object");
                    string(j, p, "name", layer.name);
                    if (layer.name.empty()) return error(p + "/name", "a layer needs a name");
                    for (const MaterialLayer& other : library) {
                        if (other.name == layer.name) {
                            return error(p + "/name", "layer '" + layer.name +
                                                          "' is defined twice; names are unique");
                        }
                    }
                    layerParameters(j, p, layer);
                })) {
                continue;  // left out: materials naming it report it as unknown
            }
            library.push_back(std::move(layer));
        }
        library_ = &library;
    }

    // A material's "layers" (names from the library, each optionally changed) and "layerMask".
    void layering(const json& j, const std::string& p, Material& m) {
        MaterialLayering& l = m.layering;
        auto it = j.find("layers");
        if (it == j.end()) return error(p + "/layers", "\"layerMask\" without \"layers\"");
        if (!it->is_array() || it->empty()) {
            return error(p + "/layers", "expected an array of 1 to " +
                                            std::to_string(kMaxMaterialLayers) + " layers");
        }
        if (it->size() > kMaxMaterialLayers) {
            return error(p + "/layers", "material '" + m.name + "' has " +
                                            std::to_string(it->size()) + " layers; at most " +
                                            std::to_string(kMaxMaterialLayers) +
                                            " (a base and three blended by the mask's R, G and B)");
        }
        for (std::size_t i = 0; i < it->size(); ++i) {
            const std::string q = p + "/layers/" + std::to_string(i);
            const json& entry = (*it)[i];
            if (!entry.is_object()) return error(q, "expected an object naming a \"layer\"");
            std::string name;
            string(entry, q, "layer", name);
            const MaterialLayer* found = nullptr;
            for (std::size_t k = 0; library_ && k < library_->size(); ++k) {
                if ((*library_)[k].name == name) found = &(*library_)[k];
            }
            if (!found) {
                std::string known;
                for (std::size_t k = 0; library_ && k < library_->size(); ++k)
                    known += (known.empty() ? "" : ", ") + (*library_)[k].name;
                return error(q + "/layer", "material '" + m.name + "': unknown layer '" + name +
                                               "' (the scene's \"materialLayers\" library has: " +
                                               (known.empty() ? std::string("none") : known) + ")");
            }
            MaterialLayer layer = *found;
            layerParameters(entry, q, layer);
            l.layers.push_back(std::move(layer));
        }
        const json* mask = nullptr;
        if (object(j, p, "layerMask", mask)) {
            enumeration(*mask, p + "/layerMask", "source", kLayerMaskSources, l.maskSource);
            textureRef(*mask, p + "/layerMask", "texture", l.maskTexture);
        }
        if (l.layers.size() > 1 && l.maskSource == LayerMaskSource::Texture &&
            !l.maskTexture.present()) {
            error(p + "/layerMask/texture",
                  "material '" + m.name + "' blends " + std::to_string(l.layers.size() - 1) +
                      " layer(s) over its base by a texture mask but names no mask texture "
                      "(give \"layerMask\": {\"texture\": {\"texture\": index}} or "
                      "\"source\": \"vertexColor\")");
        }
    }

    void light(const json& j, const std::string& p, Light& l) {
        enumeration(j, p, "type", kLightTypes, l.type);
        l.castShadows = lightTypeInfo(l.type).castsShadowsByDefault;
        boolean(j, p, kCastShadowsKey, l.castShadows);
        enumeration(j, p, "quality", kAreaLightQualities, l.quality);
        enumeration(j, p, "emission", kAreaLightEmissions, l.emission);
        // A rect's emissive image, relative to the scene file (decoded when instantiated).
        std::string texture;
        string(j, p, "texture", texture);
        if (!texture.empty()) l.texture = registerLightTexture(texture, nullptr);
        // Every field of the light type table (content/light_types.h), whatever the type.
        for (const LightFieldInfo& f : kLightFieldTable) {
            if (f.channels) {
                numbers(j, p, f.name, l.*f.channels);
            } else {
                number(j, p, f.name, l.*f.scalar);
            }
        }
        report(p, validateLight(l));
    }

    // "rigidBody" (components/rigid_body.h); values outside their domain are clamped.
    void rigidBody(const json& j, const std::string& p, RigidBody& b) {
        enumeration(j, p, "type", kBodyTypes, b.type);
        number(j, p, "mass", b.mass);
        number(j, p, "friction", b.friction);
        number(j, p, "restitution", b.restitution);
        number(j, p, "linearDamping", b.linearDamping);
        number(j, p, "angularDamping", b.angularDamping);
        number(j, p, "gravityScale", b.gravityScale);
        vector(j, p, "linearVelocity", b.linearVelocity);
        vector(j, p, "angularVelocity", b.angularVelocity);
        boolean(j, p, "canSleep", b.canSleep);
        boolean(j, p, "continuousCollision", b.continuousCollision);
        report(p, validateRigidBody(b));
    }
    // "collider" (components/collider.h): "shape" is required; sizes are optional.
    void collider(const json& j, const std::string& p, Collider& c) {
        if (!has(j, p, "shape")) error(p + "/shape", "expected the collider's shape");
        enumeration(j, p, "shape", kColliderShapes, c.shape);
        const auto optionalNumber = [&](const char* key, std::optional<float>& out) {
            if (!has(j, p, key)) return;
            float value = 0;
            number(j, p, key, value);
            out = value;
        };
        optionalNumber("radius", c.radius);
        optionalNumber("height", c.height);
        if (has(j, p, "halfExtents")) {
            ecs::Vec3 half;
            vector(j, p, "halfExtents", half);
            c.halfExtents = half;
        }
        boolean(j, p, "trigger", c.trigger);
        integer(j, p, "layer", c.layer, 0, std::numeric_limits<std::uint32_t>::max());
        integer(j, p, "mask", c.mask, 0, std::numeric_limits<std::uint32_t>::max());
        report(p, validateCollider(c));
    }
    // "audioSource" (components/audio_source.h): "clip" is required, relative to the scene file.
    void audioSource(const json& j, const std::string& p, AudioSource& a) {
        if (!has(j, p, "clip")) error(p + "/clip", "expected the clip's path (WAV or Ogg Vorbis)");
        string(j, p, "clip", a.clip);
        number(j, p, "gain", a.gain);
        number(j, p, "pitch", a.pitch);
        boolean(j, p, "loop", a.loop);
        boolean(j, p, "spatial", a.spatial);
        number(j, p, "minDistance", a.minDistance);
        number(j, p, "maxDistance", a.maxDistance);
        number(j, p, "rolloff", a.rolloff);
        bool playing = true;
        boolean(j, p, "playing", playing);
        a.state = playing ? PlaybackState::Playing : PlaybackState::Stopped;
        report(p, validateAudioSource(a));
    }
    void vector(const json& j, const std::string& p, const char* key, ecs::Vec3& out) {
        std::array<float, 3> values{out.x, out.y, out.z};
        numbers(j, p, key, values);
        out = {values[0], values[1], values[2]};
    }
    void atmosphere(const json& j, const std::string& p, Atmosphere& a) {
        numbers(j, p, "rayleighScattering", a.rayleighScattering);
        number(j, p, "rayleighScaleHeight", a.rayleighScaleHeight);
        number(j, p, "mieScattering", a.mieScattering);
        number(j, p, "mieAbsorption", a.mieAbsorption);
        number(j, p, "mieScaleHeight", a.mieScaleHeight);
        number(j, p, "mieAnisotropy", a.mieAnisotropy);
        numbers(j, p, "ozoneAbsorption", a.ozoneAbsorption);
        number(j, p, "ozoneCenterHeight", a.ozoneCenterHeight);
        number(j, p, "ozoneWidth", a.ozoneWidth);
        number(j, p, "groundRadius", a.groundRadius);
        number(j, p, "atmosphereHeight", a.atmosphereHeight);
        numbers(j, p, "groundAlbedo", a.groundAlbedo);
        number(j, p, "solarIlluminance", a.solarIlluminance);
        number(j, p, "sunAngularDiameter", a.sunAngularDiameter);
        number(j, p, "latitude", a.latitude);
        number(j, p, "dayOfYear", a.dayOfYear);
        number(j, p, "timeOfDay", a.timeOfDay);
        report(p, validateAtmosphere(a));
    }
    void camera(const json& j, const std::string& p, Camera& c) {
        enumeration(j, p, "projection", kProjections, c.projection);
        number(j, p, "verticalFov", c.verticalFov);
        number(j, p, "nearPlane", c.nearPlane);
        number(j, p, "farPlane", c.farPlane);
        number(j, p, "orthographicHalfHeight", c.orthographicHalfHeight);
        enumeration(j, p, "exposureMode", kExposureModes, c.exposureMode);
        number(j, p, "aperture", c.aperture);
        number(j, p, "shutterSeconds", c.shutterSeconds);
        number(j, p, "iso", c.iso);
        number(j, p, "manualEv100", c.manualEv100);
        number(j, p, "exposureCompensation", c.exposureCompensation);
        report(p, validateCamera(c));
    }

    // A glTF's mesh, or a built-in one; "material" is primitive 0's material override.
    void mesh(const json& m, const std::string& p, MeshReference& mesh,
              std::optional<MaterialOverride>& material) {
        string(m, p, "gltf", mesh.gltfPath);
        integer(m, p, "mesh", mesh.meshIndex, 0, std::numeric_limits<std::int32_t>::max());
        string(m, p, "builtin", mesh.builtin);
        if (!mesh.builtin.empty()) {
            if (has(m, p, "gltf") || has(m, p, "mesh")) {
                error(p + "/builtin", "give \"gltf\" or \"builtin\", not both");
            } else if (!builtinMeshFromName(mesh.builtin)) {
                error(p + "/builtin",
                      "'" + mesh.builtin + "' is not one of: " + std::string(builtinMeshNames()));
            }
        } else if (mesh.gltfPath.empty() && !has(m, p, "builtin")) {
            error(p + "/gltf",
                  "missing glTF path (or \"builtin\": " + std::string(builtinMeshNames()) + ")");
        } else if (mesh.gltfPath.empty()) {
            error(p + "/builtin", "expected a built-in mesh name");
        }
        if (const json* j = nullptr; object(m, p, "material", j)) {
            MaterialOverride entry;
            entry.primitive = 0;
            this->material(*j, p + "/material", entry.material);
            material = std::move(entry);
        }
    }

    // A clip by name (a string) or by index (an integer); whether the model has it is checked
    // when the model is loaded (instantiateScene).
    void clip(const json& object, const std::string& p, SceneClip& out) {
        known(object, p, "clip");
        auto it = object.find("clip");
        if (it == object.end()) return;
        if (it->is_string()) {
            out.name = it->get<std::string>();
            if (out.name.empty()) error(p + "/clip", "a clip name must not be empty");
        } else {
            integer(object, p, "clip", out.index, 0, std::numeric_limits<std::int32_t>::max());
        }
    }

    void animation(const json& j, const std::string& p, SceneAnimation& a) {
        clip(j, p, a.clip);
        number(j, p, "time", a.time);
        number(j, p, "speed", a.speed);
        boolean(j, p, "loop", a.loop);
        boolean(j, p, "playing", a.playing);
        if (const json* c = nullptr; object(j, p, "crossfade", c)) {
            const std::string q = p + "/crossfade";
            SceneAnimation::Crossfade fade;
            if (!c->contains("clip")) error(q + "/clip", "a crossfade needs its target clip");
            clip(*c, q, fade.clip);
            number(*c, q, "time", fade.time);
            number(*c, q, "duration", fade.duration);
            number(*c, q, "elapsed", fade.elapsed);
            if (!(fade.duration > 0)) {
                error(q + "/duration", "must be greater than 0 seconds");
            } else if (fade.elapsed < 0 || fade.elapsed > fade.duration) {
                error(q + "/elapsed", "must be between 0 and the duration");
            }
            a.crossfade = fade;
        }
    }

    SceneEntity entity(const json& j, const std::string& p, std::size_t entityCount) {
        SceneEntity e;
        if (!j.is_object()) {
            error(p, "expected an object");
            return e;
        }
        string(j, p, "name", e.name);
        if (const json* t = nullptr; object(j, p, "transform", t)) {
            Transform transform;
            if (clean([&] { this->transform(*t, p + "/transform", transform); })) {
                e.transform = transform;
            }
        }
        integer(j, p, "parent", e.parent, -1, static_cast<std::int64_t>(entityCount) - 1);
        if (const json* m = nullptr; object(j, p, "mesh", m)) {
            MeshReference mesh;
            std::optional<MaterialOverride> material;
            if (clean([&] { this->mesh(*m, p + "/mesh", mesh, material); })) {
                e.mesh = mesh;
                if (material) e.materialOverrides.push_back(std::move(*material));
            }
        }
        if (const json* m = nullptr; object(j, p, "model", m)) {
            ModelReference model;
            if (clean([&] {
                    string(*m, p + "/model", "gltf", model.gltfPath);
                    if (model.gltfPath.empty())
                        error(p + "/model/gltf", "expected the path of a glTF model");
                })) {
                e.model = model;
            }
        }
        // A bad animation block is dropped: the model still loads, its player reset.
        if (const json* a = nullptr; object(j, p, "animation", a)) {
            SceneAnimation value;
            if (clean([&] {
                    if (!e.model) {
                        return error(p + "/animation", "an animation needs the entity's \"model\"");
                    }
                    animation(*a, p + "/animation", value);
                })) {
                e.animation = value;
            }
        }
        known(j, p, "materialOverrides");
        if (auto it = j.find("materialOverrides"); it != j.end()) {
            if (!it->is_array()) error(p + "/materialOverrides", "expected an array");
            for (std::size_t i = 0; it->is_array() && i < it->size(); ++i) {
                const std::string q = p + "/materialOverrides/" + std::to_string(i);
                const json& o = (*it)[i];
                MaterialOverride entry;
                const json* m = nullptr;
                if (clean([&] {
                        if (!o.is_object()) return error(q, "expected an object");
                        integer(o, q, "primitive", entry.primitive, 0,
                                std::numeric_limits<std::int32_t>::max());
                        if (object(o, q, "material", m))
                            material(*m, q + "/material", entry.material);
                    })) {
                    e.materialOverrides.push_back(std::move(entry));
                }
            }
        }
        if (const json* l = nullptr; object(j, p, "light", l)) {
            Light value;
            if (clean([&] { light(*l, p + "/light", value); })) e.light = value;
        }
        if (const json* c = nullptr; object(j, p, "camera", c)) {
            Camera value;
            if (clean([&] { camera(*c, p + "/camera", value); })) e.camera = value;
        }
        if (const json* s = nullptr; object(j, p, "sky", s)) {
            Sky value;
            if (clean([&] {
                    string(*s, p + "/sky", "exr", value.exrPath);
                    number(*s, p + "/sky", "intensity", value.intensity);
                    report(p + "/sky", validateSky(value));
                })) {
                e.sky = value;
            }
        }
        if (const json* f = nullptr; object(j, p, "fog", f)) {
            Fog value;
            if (clean([&] {
                    const std::string q = p + "/fog";
                    number(*f, q, "scattering", value.scattering);
                    number(*f, q, "absorption", value.absorption);
                    number(*f, q, "anisotropy", value.anisotropy);
                    number(*f, q, "heightFalloff", value.heightFalloff);
                    number(*f, q, "baseHeight", value.baseHeight);
                    if (const json* b = nullptr; object(*f, q, "bounds", b)) {
                        FogBounds bounds;
                        numbers(*b, q + "/bounds", "min", bounds.min);
                        numbers(*b, q + "/bounds", "max", bounds.max);
                        for (const char* key : {"min", "max"}) {
                            if (!has(*b, q + "/bounds", key)) {
                                error(q + "/bounds/" + key,
                                      "expected an array of 3 numbers (metres, world space)");
                            }
                        }
                        value.bounds = bounds;
                    }
                    report(q, validateFog(value));
                })) {
                e.fog = value;
            }
        }
        if (const json* h = nullptr; object(j, p, "hair", h)) {
            HairGrowth value;
            if (clean([&] { hair(*h, p + "/hair", e.mesh.has_value(), value); })) e.hair = value;
        }
        if (const json* a = nullptr; object(j, p, "atmosphere", a)) {
            Atmosphere value;
            if (clean([&] { atmosphere(*a, p + "/atmosphere", value); })) e.atmosphere = value;
        }
        if (const json* b = nullptr; object(j, p, "rigidBody", b)) {
            RigidBody value;
            if (clean([&] { rigidBody(*b, p + "/rigidBody", value); })) e.rigidBody = value;
        }
        if (const json* c = nullptr; object(j, p, "collider", c)) {
            Collider value;
            if (clean([&] { collider(*c, p + "/collider", value); })) e.collider = value;
        }
        if (const json* a = nullptr; object(j, p, "audioSource", a)) {
            AudioSource value;
            if (clean([&] { audioSource(*a, p + "/audioSource", value); })) e.audioSource = value;
        }
        if (const json* l = nullptr; object(j, p, "audioListener", l)) {
            AudioListener value;
            if (clean([&] {
                    number(*l, p + "/audioListener", "gain", value.gain);
                    report(p + "/audioListener", validateAudioListener(value));
                })) {
                e.audioListener = value;
            }
        }
        if (e.rigidBody && !e.collider) {
            warning(p + "/rigidBody", "a rigid body without a \"collider\" does not move");
        }
        known(j, p, "gameData");  // the game's own: its keys are not the engine's to check
        if (auto it = j.find("gameData"); it != j.end()) e.gameDataJson = it->dump();
        return e;
    }

private:
    struct KnownKeys {
        std::string pointer;
        std::set<std::string> keys;
    };
    // The known key nearest `key` by edit distance, if within a third of its length (at least
    // 1, at most 3 edits); empty otherwise.
    static std::string closestKey(const std::string& key, const std::set<std::string>& keys) {
        std::string best;
        // Names are short; a long key is no typo, and its distances would cost its length
        // times every known key's (a fuzzed file can hold megabyte keys).
        if (key.size() > 64) return best;
        std::size_t bestDistance = std::clamp<std::size_t>(key.size() / 3, 1, 3) + 1;
        for (const std::string& candidate : keys) {
            const std::size_t d = editDistance(key, candidate);
            if (d < bestDistance) {
                bestDistance = d;
                best = candidate;
            }
        }
        return best;
    }
    // Levenshtein distance (insertions, deletions, substitutions), two rows.
    static std::size_t editDistance(const std::string& a, const std::string& b) {
        std::vector<std::size_t> previous(b.size() + 1), current(b.size() + 1);
        for (std::size_t j = 0; j <= b.size(); ++j)
            previous[j] = j;
        for (std::size_t i = 1; i <= a.size(); ++i) {
            current[0] = i;
            for (std::size_t j = 1; j <= b.size(); ++j) {
                const std::size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
                current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
            }
            std::swap(previous, current);
        }
        return previous[b.size()];
    }

    std::map<const json*, KnownKeys> known_;
    std::vector<std::string> errorPointers_;
    const std::string& file_;
    Diagnostics& diagnostics_;
    const std::vector<MaterialLayer>* library_ = nullptr;
    bool failed_ = false;
};

// Parents must name another entity and must not form cycles; offending links are cut.
void checkParents(SceneDocument& scene, Reader& reader) {
    const std::size_t count = scene.entities.size();
    for (std::size_t i = 0; i < count; ++i) {
        if (scene.entities[i].parent == static_cast<std::int32_t>(i)) {
            reader.error("/entities/" + std::to_string(i) + "/parent", "entity is its own parent");
            scene.entities[i].parent = kNoIndex;
        }
    }
    std::vector<std::int32_t> walkOf(count, -1);
    std::vector<bool> done(count, false);
    for (std::size_t start = 0; start < count; ++start) {
        std::int32_t at = static_cast<std::int32_t>(start);
        while (at != kNoIndex && !done[static_cast<std::size_t>(at)]) {
            auto i = static_cast<std::size_t>(at);
            if (walkOf[i] == static_cast<std::int32_t>(start)) {
                reader.error("/entities/" + std::to_string(i) + "/parent",
                             "parent links form a cycle; link removed");
                scene.entities[i].parent = kNoIndex;
                break;
            }
            walkOf[i] = static_cast<std::int32_t>(start);
            at = scene.entities[i].parent;
        }
        for (at = static_cast<std::int32_t>(start);
             at != kNoIndex && !done[static_cast<std::size_t>(at)];
             at = scene.entities[static_cast<std::size_t>(at)].parent) {
            done[static_cast<std::size_t>(at)] = true;
        }
    }
}

std::string lineAndColumn(std::span<const std::byte> bytes, std::size_t byteOffset) {
    std::size_t line = 1;
    std::size_t column = 1;
    for (std::size_t i = 0; i + 1 < byteOffset && i < bytes.size(); ++i) {
        if (bytes[i] == std::byte{'\n'}) {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

constexpr std::size_t kMaxNestingDepth = 128;

}  // namespace

std::optional<SceneDocument> parseSceneJson(std::span<const std::byte> bytes,
                                            const std::string& name, Diagnostics& diagnostics) {
    json root;
    try {
        root = json::parse(reinterpret_cast<const char*>(bytes.data()),
                           reinterpret_cast<const char*>(bytes.data()) + bytes.size());
    } catch (const json::parse_error& e) {
        diagnostics.error(name, "",
                          "invalid JSON at " + lineAndColumn(bytes, e.byte) + ": " + e.what());
        return std::nullopt;
    } catch (const json::exception& e) {
        // Not only parse_error: a number too large for a double throws out_of_range (found by
        // fuzz_scene_file; tests/content/regressions/scene/).
        diagnostics.error(name, "", std::string("invalid JSON: ") + e.what());
        return std::nullopt;
    }
    Reader reader(name, diagnostics);
    if (nestingDepth(root) > kMaxNestingDepth) {
        reader.error("", "JSON nesting deeper than " + std::to_string(kMaxNestingDepth));
        return std::nullopt;
    }
    if (!root.is_object()) {
        reader.error("", "expected a JSON object at the top level");
        return std::nullopt;
    }
    for (const char* key : {"format", "version", "entities"})
        reader.known(root, "", key);
    if (auto format = root.find("format"); format == root.end() || *format != kFormatName) {
        reader.error("/format", "missing or not \"" + std::string(kFormatName) + "\"");
        return std::nullopt;
    }
    auto version = root.find("version");
    if (version == root.end() || !version->is_number_integer()) {
        reader.error("/version", "missing or not an integer");
        return std::nullopt;
    }
    if (version->get<std::int64_t>() > kSceneFileVersion || version->get<std::int64_t>() < 1) {
        reader.error("/version", "version " + version->dump() +
                                     " is not supported (this build reads 1 to " +
                                     std::to_string(kSceneFileVersion) + ")");
        return std::nullopt;
    }
    auto entities = root.find("entities");
    if (entities == root.end() || !entities->is_array()) {
        reader.error("/entities", "missing or not an array");
        return std::nullopt;
    }
    SceneDocument scene;
    // A top-level choice among named values, when present: a bad name is reported and the
    // field left unset (the engine's default).
    auto optionalEnumeration = [&](const char* key, const auto& names, auto& field) {
        if (!reader.has(root, "", key)) return;
        typename std::remove_reference_t<decltype(field)>::value_type value{};
        if (reader.clean([&] { reader.enumeration(root, "", key, names, value); })) field = value;
    };
    // Every render setting under its key (render_setting_table.h). A bad value is reported and
    // the setting left unset (the preset's): the scene still loads.
    forEachRenderSetting(
        [&](const auto& row) { reader.renderSetting(root, row, scene.settings.*row.choice); });
    optionalEnumeration("quality", kQualityLevelNames, scene.quality);
    const json* ao = nullptr;
    if (reader.object(root, "", "ambient_occlusion", ao)) {
        // Like the settings: a bad value is reported and its default kept.
        SceneAmbientOcclusion settings;
        float radius = settings.radius;
        if (reader.clean([&] { reader.number(*ao, "/ambient_occlusion", "radius", radius); })) {
            if (radius > 0.0f) {
                settings.radius = radius;
            } else {
                reader.error("/ambient_occlusion/radius", "must be greater than 0 (metres)");
            }
        }
        float intensity = settings.intensity;
        if (reader.clean(
                [&] { reader.number(*ao, "/ambient_occlusion", "intensity", intensity); })) {
            if (intensity >= 0.0f && intensity <= 1.0f) {
                settings.intensity = intensity;
            } else {
                reader.error("/ambient_occlusion/intensity", "must be between 0 and 1");
            }
        }
        scene.ambientOcclusion = settings;
    }
    reader.layerLibrary(root, scene.materialLayers);
    scene.entities.reserve(entities->size());
    for (std::size_t i = 0; i < entities->size(); ++i) {
        scene.entities.push_back(
            reader.entity((*entities)[i], "/entities/" + std::to_string(i), entities->size()));
    }
    checkParents(scene, reader);
    reader.reportUnknownKeys();
    return scene;
}

}  // namespace candela::content
