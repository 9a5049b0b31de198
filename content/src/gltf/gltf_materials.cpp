// glTF materials (core, KHR_materials_emissive_strength, KHR_materials_unlit,
// KHR_materials_specular, KHR_materials_anisotropy, KHR_materials_clearcoat,
// KHR_texture_transform) and the engine's `extras` -> Model::materials.
#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "candela/content/component_validation.h"
#include "gltf_context.h"
#include "gltf_values.h"

namespace candela::content::gltf {
namespace {

// Reads KHR_texture_transform from a textureInfo's extensions.
void readTextureTransform(Context& context, const std::string& element,
                          const tinygltf::ExtensionMap& extensions, TextureRef& ref) {
    auto it = extensions.find("KHR_texture_transform");
    if (it == extensions.end()) return;
    const tinygltf::Value& ext = it->second;
    TextureTransform& t = ref.transform;
    if (member(ext, "offset") && !readNumbers(ext, "offset", t.offset)) {
        context.warning(element, "KHR_texture_transform.offset is not two finite numbers; ignored");
    }
    if (member(ext, "scale") && !readNumbers(ext, "scale", t.scale)) {
        context.warning(element, "KHR_texture_transform.scale is not two finite numbers; ignored");
    }
    if (member(ext, "rotation") && !readNumber(ext, "rotation", t.rotation)) {
        context.warning(element, "KHR_texture_transform.rotation is not a finite number; ignored");
    }
    float texCoord = 0;
    if (readNumber(ext, "texCoord", texCoord)) {
        ref.texCoord = static_cast<std::uint32_t>(std::clamp(texCoord, 0.0f, 1.0f));
    }
}

// Fills `ref` from a texture index and texCoord, checking both. An index that names no
// texture is replaced by the magenta checker, so the mistake is visible.
TextureRef makeTextureRef(Context& context, const std::string& element, int index, int texCoord,
                          const tinygltf::ExtensionMap& extensions, ColorSpace colorSpace) {
    TextureRef ref;
    if (index < 0) return ref;
    ref.colorSpace = colorSpace;
    if (validIndex(index, context.document.textures)) {
        ref.texture = index;
    } else {
        context.error(element, "texture " + std::to_string(index) +
                                   " does not exist; using the magenta checker");
        ref.texture = fallbackTextureIndex(context);
    }
    if (texCoord < 0 || texCoord > 1) {
        context.warning(element, "texCoord " + std::to_string(texCoord) +
                                     " is not supported (only 0 and 1); using 0");
        texCoord = 0;
    }
    ref.texCoord = static_cast<std::uint32_t>(texCoord);
    readTextureTransform(context, element, extensions, ref);
    return ref;
}

// A textureInfo stored as a raw Value (inside an extension).
TextureRef makeTextureRef(Context& context, const std::string& element, const tinygltf::Value& info,
                          ColorSpace colorSpace) {
    float index = -1;
    float texCoord = 0;
    if (!readNumber(info, "index", index)) return {};
    readNumber(info, "texCoord", texCoord);
    tinygltf::ExtensionMap extensions;
    if (const tinygltf::Value* ext = member(info, "extensions"); ext && ext->IsObject()) {
        for (const std::string& key : ext->Keys())
            extensions[key] = ext->Get(key);
    }
    return makeTextureRef(context, element, static_cast<int>(std::clamp(index, -1.0f, 1e9f)),
                          static_cast<int>(std::clamp(texCoord, -1.0f, 1e9f)), extensions,
                          colorSpace);
}

template <std::size_t N>
void copyFactorsOrWarn(Context& context, const std::string& element, const char* what,
                       const std::vector<double>& in, std::array<float, N>& out) {
    if (!in.empty() && !copyFactors(in, out)) {
        context.warning(element, std::string(what) + " is not " + std::to_string(N) +
                                     " finite numbers; using the default");
    }
}

void readSpecularExtension(Context& context, const std::string& element, const tinygltf::Value& ext,
                           Material& material) {
    float factor = 1;
    readNumber(ext, "specularFactor", factor);
    readNumbers(ext, "specularColorFactor", material.specularColorFactor);
    if (const tinygltf::Value* t = member(ext, "specularTexture")) {
        material.specularTexture = makeTextureRef(context, element, *t, ColorSpace::Linear);
    }
    if (const tinygltf::Value* t = member(ext, "specularColorTexture")) {
        material.specularColorTexture = makeTextureRef(context, element, *t, ColorSpace::Srgb);
    }
    // glTF: dielectric F0 = 0.04 * specularFactor * specularColor (for ior 1.5).
    // Engine: F0 = 0.08 * specular. The engine has one scalar, so the colour's largest
    // channel is used; the colour factor itself is kept on the material.
    const auto& c = material.specularColorFactor;
    const float mapped = 0.5f * factor * std::max({c[0], c[1], c[2]});
    material.specular = std::clamp(mapped, 0.0f, 1.0f);
    if (mapped != material.specular) {
        context.warning(element,
                        "KHR_materials_specular gives F0 beyond the engine's range "
                        "(specular " +
                            std::to_string(mapped) + " clamped to [0, 1])");
    }
}

void readAnisotropyExtension(Context& context, const std::string& element,
                             const tinygltf::Value& ext, Material& material) {
    float strength = 0;
    if (member(ext, "anisotropyStrength") && !readNumber(ext, "anisotropyStrength", strength)) {
        context.warning(element, "anisotropyStrength is not a finite number; using 0");
    }
    material.anisotropyStrength = std::clamp(strength, 0.0f, 1.0f);
    if (strength != material.anisotropyStrength) {
        context.warning(element, "anisotropyStrength " + std::to_string(strength) +
                                     " is outside [0, 1]; clamped");
    }
    if (member(ext, "anisotropyRotation") &&
        !readNumber(ext, "anisotropyRotation", material.anisotropyRotation)) {
        context.warning(element, "anisotropyRotation is not a finite number; using 0");
    }
    if (const tinygltf::Value* t = member(ext, "anisotropyTexture")) {
        material.anisotropyTexture =
            makeTextureRef(context, element + ".anisotropyTexture", *t, ColorSpace::Linear);
    }
}

void readClearcoatExtension(Context& context, const std::string& element,
                            const tinygltf::Value& ext, Material& material) {
    auto unit = [&](const char* key, float& out) {
        if (!member(ext, key)) return;
        float v = 0;
        if (!readNumber(ext, key, v)) {
            context.warning(element, std::string(key) + " is not a finite number; using 0");
            return;
        }
        out = std::clamp(v, 0.0f, 1.0f);
        if (out != v) context.warning(element, std::string(key) + " is outside [0, 1]; clamped");
    };
    unit("clearcoatFactor", material.clearcoatFactor);
    unit("clearcoatRoughnessFactor", material.clearcoatRoughnessFactor);
    if (const tinygltf::Value* t = member(ext, "clearcoatTexture")) {
        material.clearcoatTexture =
            makeTextureRef(context, element + ".clearcoatTexture", *t, ColorSpace::Linear);
    }
    if (const tinygltf::Value* t = member(ext, "clearcoatRoughnessTexture")) {
        material.clearcoatRoughnessTexture =
            makeTextureRef(context, element + ".clearcoatRoughnessTexture", *t, ColorSpace::Linear);
    }
    if (const tinygltf::Value* t = member(ext, "clearcoatNormalTexture")) {
        material.clearcoatNormalTexture =
            makeTextureRef(context, element + ".clearcoatNormalTexture", *t, ColorSpace::Linear);
        readNumber(*t, "scale", material.clearcoatNormalScale);
    }
}

// extras.cavity (UE4's Cavity, [0, 1]): unlike the other extras, a value out of range is
// named in a warning before it is clamped, since a cavity of 2 or -1 is a mistake.
void readCavityExtra(Context& context, const std::string& element, const tinygltf::Value& extras,
                     Material& material) {
    if (!member(extras, "cavity")) return;
    const std::string where = "extras.cavity of material '" + material.name + "'";
    float cavity = 1;
    if (!readNumber(extras, "cavity", cavity)) {
        context.warning(element, where + " is not a finite number; ignored (using 1)");
        return;
    }
    material.cavity = std::clamp(cavity, 0.0f, 1.0f);
    if (material.cavity != cavity) {
        context.warning(element, where + " " + std::to_string(cavity) +
                                     " is outside [0, 1]; clamped to " +
                                     std::to_string(material.cavity));
    }
}

// extras.wireRadius (Persson 2014, GPU Pro 5, "Wire Antialiasing"): the radius in metres of the
// wires drawn with this material. Anything but a finite positive number is an error: the lines then
// stay skipped.
void readWireRadiusExtra(Context& context, const std::string& element,
                         const tinygltf::Value& extras, Material& material) {
    const tinygltf::Value* value = member(extras, "wireRadius");
    if (value == nullptr) return;
    const double radius =
        value->IsNumber() ? value->GetNumberAsDouble() : std::numeric_limits<double>::quiet_NaN();
    if (!value->IsNumber() || !std::isfinite(radius) || radius <= 0.0 ||
        radius > double(std::numeric_limits<float>::max())) {
        const std::string given = value->IsNumber() ? std::to_string(radius) : "not a number";
        context.error(element + ".wireRadius",
                      "material '" + material.name + "': a wire radius must be a finite number " +
                          "of metres above 0 (given: " + given + "); its lines are skipped");
        return;
    }
    material.wireRadius = float(radius);
}

// extras.hair (Martin et al. 2014, GPU Pro 5, "TressFX: Advanced Real-Time Hair Rendering"): the
// material's line primitives are hair strands of this style. Every key is optional (HairStyle's
// defaults); a key that is present but wrong (a radius not a finite number of metres above 0, a
// colour not three finite numbers in [0, 1], a shift not finite, an exponent not a finite number
// above 0) is an error naming materials[i].extras.hair.<key>, and the material makes no hair (its
// lines stay skipped).
void readHairExtra(Context& context, const std::string& element, const tinygltf::Value& extras,
                   bool emptyHair, Material& material) {
    const tinygltf::Value* hair = member(extras, "hair");
    if (hair == nullptr) {
        if (emptyHair) material.hair = HairStyle{};  // every key left at its default
        return;
    }
    const std::string where = element + ".hair";
    if (!hair->IsObject()) {
        context.error(where, "material '" + material.name +
                                 "': hair must be an object (rootRadius, tipRadius, color, "
                                 "primaryShift, secondaryShift, primaryExponent, "
                                 "secondaryExponent); its lines are skipped");
        return;
    }
    HairStyle style;
    bool valid = true;
    auto number = [&](const char* key, float& out, float above, const char* rule) {
        const tinygltf::Value* value = member(*hair, key);
        if (value == nullptr) return;
        float v = 0;
        if (!readNumber(*hair, key, v) || !(v > above)) {
            const std::string given =
                value->IsNumber() ? std::to_string(value->GetNumberAsDouble()) : "not a number";
            context.error(where + "." + key, "material '" + material.name + "': " + rule +
                                                 " (given: " + given + "); its lines are skipped");
            valid = false;
            return;
        }
        out = v;
    };
    const float lowest = -std::numeric_limits<float>::max();
    number("rootRadius", style.rootRadius, 0.0f,
           "a radius must be a finite number of metres above 0");
    style.tipRadius = style.rootRadius;  // a tip radius not given: the strand keeps its width
    number("tipRadius", style.tipRadius, 0.0f,
           "a radius must be a finite number of metres above 0");
    number("primaryShift", style.primaryShift, lowest, "a shift must be a finite number");
    number("secondaryShift", style.secondaryShift, lowest, "a shift must be a finite number");
    number("primaryExponent", style.primaryExponent, 0.0f,
           "an exponent must be a finite number above 0");
    number("secondaryExponent", style.secondaryExponent, 0.0f,
           "an exponent must be a finite number above 0");
    if (member(*hair, "color") != nullptr) {
        std::array<float, 3> color{};
        if (!readNumbers(*hair, "color", color) ||
            std::any_of(color.begin(), color.end(), [](float c) { return c < 0.0f || c > 1.0f; })) {
            context.error(where + ".color",
                          "material '" + material.name +
                              "': a hair colour must be three finite numbers in [0, 1] (linear "
                              "RGB); its lines are skipped");
            valid = false;
        } else {
            style.color = color;
        }
    }
    if (valid) material.hair = style;
}

// Whether the extras' original JSON holds `key` as an empty object: tinygltf's value tree drops
// empty objects (and an extras object left empty by that), so `"hair": {}` (hair in every
// default) is only visible in the text it keeps (SetStoreOriginalJSONForExtrasAndExtensions).
bool hasEmptyObject(const std::string& extrasJson, const char* key) {
    if (extrasJson.find(key) == std::string::npos) return false;
    const nlohmann::json extras = nlohmann::json::parse(extrasJson, nullptr, false);
    if (!extras.is_object()) return false;
    const auto it = extras.find(key);
    return it != extras.end() && it->is_object() && it->empty();
}

void readEngineExtras(Context& context, const std::string& element, const tinygltf::Value& extras,
                      const std::string& extrasJson, Material& material) {
    const bool emptyHair = hasEmptyObject(extrasJson, "hair");
    if (!extras.IsObject()) {
        if (emptyHair) material.hair = HairStyle{};
        return;
    }
    if (std::string model; readString(extras, "shadingModel", model)) {
        if (model == "defaultLit")
            material.shadingModel = ShadingModel::DefaultLit;
        else if (model == "subsurface")
            material.shadingModel = ShadingModel::Subsurface;
        else if (model == "legacy")
            material.shadingModel = ShadingModel::Legacy;
        else if (model == "unlit")
            material.shadingModel = ShadingModel::Unlit;
        else
            context.warning(element, "extras.shadingModel '" + model +
                                         "' is unknown (defaultLit, subsurface, legacy, unlit)");
    }
    auto number = [&](const char* key, float& out, float lo, float hi) {
        if (!member(extras, key)) return;
        float v = 0;
        if (!readNumber(extras, key, v)) {
            context.warning(element, std::string("extras.") + key + " is not a finite number");
            return;
        }
        out = std::clamp(v, lo, hi);
    };
    auto color = [&](const char* key, std::array<float, 3>& out) {
        if (member(extras, key) && !readNumbers(extras, key, out)) {
            context.warning(element, std::string("extras.") + key + " is not 3 finite numbers");
        }
    };
    number("specular", material.specular, 0.0f, 1.0f);
    color("subsurfaceColor", material.subsurfaceColor);
    number("subsurfaceOpacity", material.subsurfaceOpacity, 0.0f, 1.0f);
    color("diffuseColor", material.diffuseColor);
    color("specularColor", material.specularColor);
    readCavityExtra(context, element, extras, material);
    readWireRadiusExtra(context, element, extras, material);
    readHairExtra(context, element, extras, emptyHair, material);
}

Material convertMaterial(Context& context, const tinygltf::Material& source,
                         const std::string& element) {
    Material material;
    material.name = source.name;
    const auto& pbr = source.pbrMetallicRoughness;
    copyFactorsOrWarn(context, element, "baseColorFactor", pbr.baseColorFactor,
                      material.baseColorFactor);
    copyFactorsOrWarn(context, element, "emissiveFactor", source.emissiveFactor,
                      material.emissiveFactor);
    auto scalar = [&](const char* what, double in, float& out) {
        if (!toFiniteFloat(in, out)) context.warning(element, std::string(what) + " is not finite");
    };
    scalar("metallicFactor", pbr.metallicFactor, material.metallicFactor);
    scalar("roughnessFactor", pbr.roughnessFactor, material.roughnessFactor);
    scalar("normalTexture.scale", source.normalTexture.scale, material.normalScale);
    scalar("occlusionTexture.strength", source.occlusionTexture.strength,
           material.occlusionStrength);
    scalar("alphaCutoff", source.alphaCutoff, material.alphaCutoff);
    material.metallicFactor = std::clamp(material.metallicFactor, 0.0f, 1.0f);
    material.roughnessFactor = std::clamp(material.roughnessFactor, 0.0f, 1.0f);
    material.occlusionStrength = std::clamp(material.occlusionStrength, 0.0f, 1.0f);

    material.baseColorTexture = makeTextureRef(
        context, element + ".pbrMetallicRoughness.baseColorTexture", pbr.baseColorTexture.index,
        pbr.baseColorTexture.texCoord, pbr.baseColorTexture.extensions, ColorSpace::Srgb);
    material.metallicRoughnessTexture =
        makeTextureRef(context, element + ".pbrMetallicRoughness.metallicRoughnessTexture",
                       pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord,
                       pbr.metallicRoughnessTexture.extensions, ColorSpace::Linear);
    material.normalTexture = makeTextureRef(
        context, element + ".normalTexture", source.normalTexture.index,
        source.normalTexture.texCoord, source.normalTexture.extensions, ColorSpace::Linear);
    material.occlusionTexture = makeTextureRef(
        context, element + ".occlusionTexture", source.occlusionTexture.index,
        source.occlusionTexture.texCoord, source.occlusionTexture.extensions, ColorSpace::Linear);
    material.emissiveTexture = makeTextureRef(
        context, element + ".emissiveTexture", source.emissiveTexture.index,
        source.emissiveTexture.texCoord, source.emissiveTexture.extensions, ColorSpace::Srgb);

    if (source.alphaMode == "MASK")
        material.alphaMode = AlphaMode::Mask;
    else if (source.alphaMode == "BLEND")
        material.alphaMode = AlphaMode::Blend;
    else if (!source.alphaMode.empty() && source.alphaMode != "OPAQUE")
        context.warning(element, "alphaMode '" + source.alphaMode + "' is unknown; using OPAQUE");
    material.doubleSided = source.doubleSided;

    const auto& extensions = source.extensions;
    if (auto it = extensions.find("KHR_materials_emissive_strength"); it != extensions.end()) {
        readNumber(it->second, "emissiveStrength", material.emissiveStrength);
        material.emissiveStrength = std::max(material.emissiveStrength, 0.0f);
    }
    if (extensions.count("KHR_materials_unlit") != 0) {
        material.shadingModel = ShadingModel::Unlit;
    }
    if (auto it = extensions.find("KHR_materials_specular"); it != extensions.end()) {
        readSpecularExtension(context, element + ".extensions.KHR_materials_specular", it->second,
                              material);
    }
    if (auto it = extensions.find("KHR_materials_anisotropy"); it != extensions.end()) {
        readAnisotropyExtension(context, element + ".extensions.KHR_materials_anisotropy",
                                it->second, material);
    }
    if (auto it = extensions.find("KHR_materials_clearcoat"); it != extensions.end()) {
        readClearcoatExtension(context, element + ".extensions.KHR_materials_clearcoat", it->second,
                               material);
    }
    // Extras come last: an engine-specific value wins over what an extension implied.
    readEngineExtras(context, element + ".extras", source.extras, source.extras_json_string,
                     material);
    // Shared with the scene loader: emission that would overflow the shaders is clamped.
    for (const ValueProblem& problem : validateEmission(material)) {
        context.warning(element, problem.field + ": " + problem.message);
    }
    return material;
}

}  // namespace

void convertMaterials(Context& context) {
    const auto& materials = context.document.materials;
    context.model.materials.reserve(materials.size());
    for (std::size_t i = 0; i < materials.size(); ++i) {
        context.model.materials.push_back(
            convertMaterial(context, materials[i], elementName("materials", i)));
    }
}

}  // namespace candela::content::gltf
