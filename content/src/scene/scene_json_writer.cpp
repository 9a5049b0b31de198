// SceneDocument -> JSON text. Every field is written, so reading it back needs no defaults
// and round-trips exactly (floats print in shortest form that parses back to the same value).
#include <nlohmann/json.hpp>

#include <cmath>

#include "candela/content/light_texture.h"
#include "candela/content/render_setting_table.h"
#include "candela/content/scene_file.h"
#include "scene_json_names.h"

namespace candela::content {
namespace {

using nlohmann::json;
using namespace scene;

// Non-finite values have no JSON spelling; they are collected as errors instead of written.
struct Writer {
    std::string error;

    json number(float v, const std::string& pointer) {
        if (!std::isfinite(v) && error.empty()) error = pointer + ": value is NaN or Inf";
        return v;
    }
    template <std::size_t N>
    json numbers(const std::array<float, N>& values, const std::string& pointer) {
        json out = json::array();
        for (float v : values)
            out.push_back(number(v, pointer));
        return out;
    }

    json transform(const Transform& t, const std::string& p) {
        return {{"translation", numbers(t.translation, p + "/translation")},
                {"rotation", numbers(t.rotation, p + "/rotation")},
                {"scale", numbers(t.scale, p + "/scale")}};
    }

    json textureRef(const TextureRef& t, const std::string& p) {
        return {{"texture", t.texture},
                {"texCoord", t.texCoord},
                {"colorSpace", nameOf(kColorSpaces, t.colorSpace)},
                {"offset", numbers(t.transform.offset, p + "/offset")},
                {"rotation", number(t.transform.rotation, p + "/rotation")},
                {"scale", numbers(t.transform.scale, p + "/scale")}};
    }

    json material(const Material& m, const std::string& p) {
        json out = baseMaterial(m, p);
        // Cavity only when set, so files of materials without it stay as they were.
        if (m.cavity != 1.0f) out["cavity"] = number(m.cavity, p + "/cavity");
        // The extensions only when used, so files of materials without them stay as they were.
        if (m.anisotropic() || m.anisotropyTexture.present()) {
            out["anisotropyStrength"] = number(m.anisotropyStrength, p + "/anisotropyStrength");
            out["anisotropyRotation"] = number(m.anisotropyRotation, p + "/anisotropyRotation");
            out["anisotropyTexture"] = textureRef(m.anisotropyTexture, p + "/anisotropyTexture");
        }
        if (m.clearCoated() || m.clearcoatTexture.present()) {
            out["clearcoatFactor"] = number(m.clearcoatFactor, p + "/clearcoatFactor");
            out["clearcoatTexture"] = textureRef(m.clearcoatTexture, p + "/clearcoatTexture");
            out["clearcoatRoughnessFactor"] =
                number(m.clearcoatRoughnessFactor, p + "/clearcoatRoughnessFactor");
            out["clearcoatRoughnessTexture"] =
                textureRef(m.clearcoatRoughnessTexture, p + "/clearcoatRoughnessTexture");
            out["clearcoatNormalTexture"] =
                textureRef(m.clearcoatNormalTexture, p + "/clearcoatNormalTexture");
            out["clearcoatNormalScale"] =
                number(m.clearcoatNormalScale, p + "/clearcoatNormalScale");
        }
        // Layers only when used, so files of materials without them stay as they were.
        if (m.layered()) {
            json layers = json::array();
            for (std::size_t i = 0; i < m.layering.layers.size(); ++i) {
                const std::string q = p + "/layers/" + std::to_string(i);
                json entry = layer(m.layering.layers[i], q);
                entry["layer"] = m.layering.layers[i].name;
                entry.erase("name");
                layers.push_back(std::move(entry));
            }
            out["layers"] = std::move(layers);
            out["layerMask"] = {
                {"source", nameOf(kLayerMaskSources, m.layering.maskSource)},
                {"texture", textureRef(m.layering.maskTexture, p + "/layerMask/texture")}};
        }
        return out;
    }

    json layer(const MaterialLayer& l, const std::string& p) {
        return {
            {"name", l.name},
            {"baseColorFactor", numbers(l.baseColorFactor, p + "/baseColorFactor")},
            {"metallicFactor", number(l.metallicFactor, p + "/metallicFactor")},
            {"roughnessFactor", number(l.roughnessFactor, p + "/roughnessFactor")},
            {"specular", number(l.specular, p + "/specular")},
            {"normalScale", number(l.normalScale, p + "/normalScale")},
            {"baseColorTexture", textureRef(l.baseColorTexture, p + "/baseColorTexture")},
            {"metallicRoughnessTexture",
             textureRef(l.metallicRoughnessTexture, p + "/metallicRoughnessTexture")},
            {"normalTexture", textureRef(l.normalTexture, p + "/normalTexture")},
            {"uvScale", numbers(l.uvScale, p + "/uvScale")},
        };
    }

    json baseMaterial(const Material& m, const std::string& p) {
        return {
            {"name", m.name},
            {"shadingModel", nameOf(kShadingModels, m.shadingModel)},
            {"baseColorFactor", numbers(m.baseColorFactor, p + "/baseColorFactor")},
            {"baseColorTexture", textureRef(m.baseColorTexture, p + "/baseColorTexture")},
            {"metallicFactor", number(m.metallicFactor, p + "/metallicFactor")},
            {"roughnessFactor", number(m.roughnessFactor, p + "/roughnessFactor")},
            {"metallicRoughnessTexture",
             textureRef(m.metallicRoughnessTexture, p + "/metallicRoughnessTexture")},
            {"normalTexture", textureRef(m.normalTexture, p + "/normalTexture")},
            {"normalScale", number(m.normalScale, p + "/normalScale")},
            {"occlusionTexture", textureRef(m.occlusionTexture, p + "/occlusionTexture")},
            {"occlusionStrength", number(m.occlusionStrength, p + "/occlusionStrength")},
            {"emissiveTexture", textureRef(m.emissiveTexture, p + "/emissiveTexture")},
            {"emissiveFactor", numbers(m.emissiveFactor, p + "/emissiveFactor")},
            {"emissiveStrength", number(m.emissiveStrength, p + "/emissiveStrength")},
            {"alphaMode", nameOf(kAlphaModes, m.alphaMode)},
            {"alphaCutoff", number(m.alphaCutoff, p + "/alphaCutoff")},
            {"doubleSided", m.doubleSided},
            {"specular", number(m.specular, p + "/specular")},
            {"specularTexture", textureRef(m.specularTexture, p + "/specularTexture")},
            {"specularColorTexture",
             textureRef(m.specularColorTexture, p + "/specularColorTexture")},
            {"specularColorFactor", numbers(m.specularColorFactor, p + "/specularColorFactor")},
            {"subsurfaceColor", numbers(m.subsurfaceColor, p + "/subsurfaceColor")},
            {"subsurfaceOpacity", number(m.subsurfaceOpacity, p + "/subsurfaceOpacity")},
            {"diffuseColor", numbers(m.diffuseColor, p + "/diffuseColor")},
            {"specularColor", numbers(m.specularColor, p + "/specularColor")},
        };
    }

    json light(const Light& l, const std::string& p) {
        json out = {{"type", nameOf(kLightTypes, l.type)}};
        // Every field of the light type table (content/light_types.h), whatever the type.
        for (const LightFieldInfo& f : kLightFieldTable) {
            const std::string pointer = p + "/" + f.name;
            out[f.name] =
                f.channels ? numbers(l.*f.channels, pointer) : number(l.*f.scalar, pointer);
        }
        out[kCastShadowsKey] = l.castShadows;
        if (l.quality != AreaLightQuality::Default) {
            out["quality"] = nameOf(kAreaLightQualities, l.quality);
        }
        if (l.emission != AreaLightEmission::Lambertian) {
            out["emission"] = nameOf(kAreaLightEmissions, l.emission);
        }
        if (const auto texture = findLightTexture(l.texture); texture && !texture->file.empty()) {
            out["texture"] = texture->file;
        }
        return out;
    }

    json vector(ecs::Vec3 v, const std::string& pointer) {
        return numbers(std::array<float, 3>{v.x, v.y, v.z}, pointer);
    }

    // Every field, so a saved body reads back the same whatever the defaults become.
    json rigidBody(const RigidBody& b, const std::string& q) {
        return {{"type", nameOf(kBodyTypes, b.type)},
                {"mass", number(b.mass, q + "mass")},
                {"friction", number(b.friction, q + "friction")},
                {"restitution", number(b.restitution, q + "restitution")},
                {"linearDamping", number(b.linearDamping, q + "linearDamping")},
                {"angularDamping", number(b.angularDamping, q + "angularDamping")},
                {"gravityScale", number(b.gravityScale, q + "gravityScale")},
                {"linearVelocity", vector(b.linearVelocity, q + "linearVelocity")},
                {"angularVelocity", vector(b.angularVelocity, q + "angularVelocity")},
                {"canSleep", b.canSleep},
                {"continuousCollision", b.continuousCollision}};
    }

    // Sizes only where the scene gave them (unset ones fit the entity's mesh).
    json collider(const Collider& c, const std::string& q) {
        json out = {{"shape", nameOf(kColliderShapes, c.shape)}};
        if (c.radius) out["radius"] = number(*c.radius, q + "radius");
        if (c.halfExtents) out["halfExtents"] = vector(*c.halfExtents, q + "halfExtents");
        if (c.height) out["height"] = number(*c.height, q + "height");
        if (c.trigger) out["trigger"] = true;
        if (c.layer != kDefaultCollisionLayer) out["layer"] = c.layer;
        if (c.mask != kAllCollisionLayers) out["mask"] = c.mask;
        return out;
    }

    json audioSource(const AudioSource& a, const std::string& q) {
        json out = {{"clip", a.clip},
                    {"gain", number(a.gain, q + "gain")},
                    {"pitch", number(a.pitch, q + "pitch")},
                    {"loop", a.loop},
                    {"spatial", a.spatial},
                    {"minDistance", number(a.minDistance, q + "minDistance")},
                    {"maxDistance", number(a.maxDistance, q + "maxDistance")},
                    {"rolloff", number(a.rolloff, q + "rolloff")}};
        if (a.state == PlaybackState::Stopped) out["playing"] = false;
        return out;
    }

    json camera(const Camera& c, const std::string& p) {
        return {
            {"projection", nameOf(kProjections, c.projection)},
            {"verticalFov", number(c.verticalFov, p + "/verticalFov")},
            {"nearPlane", number(c.nearPlane, p + "/nearPlane")},
            {"farPlane", number(c.farPlane, p + "/farPlane")},
            {"orthographicHalfHeight",
             number(c.orthographicHalfHeight, p + "/orthographicHalfHeight")},
            {"exposureMode", nameOf(kExposureModes, c.exposureMode)},
            {"aperture", number(c.aperture, p + "/aperture")},
            {"shutterSeconds", number(c.shutterSeconds, p + "/shutterSeconds")},
            {"iso", number(c.iso, p + "/iso")},
            {"manualEv100", number(c.manualEv100, p + "/manualEv100")},
            {"exposureCompensation", number(c.exposureCompensation, p + "/exposureCompensation")}};
    }

    static json clip(const SceneClip& c) { return c.name.empty() ? json(c.index) : json(c.name); }

    json animation(const SceneAnimation& a, const std::string& p) {
        json out = {{"clip", clip(a.clip)},
                    {"time", number(a.time, p + "/time")},
                    {"speed", number(a.speed, p + "/speed")},
                    {"loop", a.loop},
                    {"playing", a.playing}};
        if (a.crossfade) {
            const std::string q = p + "/crossfade";
            out["crossfade"] = {{"clip", clip(a.crossfade->clip)},
                                {"time", number(a.crossfade->time, q + "/time")},
                                {"duration", number(a.crossfade->duration, q + "/duration")},
                                {"elapsed", number(a.crossfade->elapsed, q + "/elapsed")}};
        }
        return out;
    }

    json entity(const SceneEntity& e, const std::string& p) {
        json out = {{"name", e.name}, {"transform", transform(e.transform, p + "/transform")}};
        if (e.parent != kNoIndex) out["parent"] = e.parent;
        if (e.mesh && !e.mesh->builtin.empty()) {
            out["mesh"] = {{"builtin", e.mesh->builtin}};
        } else if (e.mesh) {
            out["mesh"] = {{"gltf", e.mesh->gltfPath}, {"mesh", e.mesh->meshIndex}};
        }
        if (e.model) out["model"] = {{"gltf", e.model->gltfPath}};
        if (e.animation) out["animation"] = animation(*e.animation, p + "/animation");
        if (!e.materialOverrides.empty()) {
            json overrides = json::array();
            for (std::size_t i = 0; i < e.materialOverrides.size(); ++i) {
                const MaterialOverride& o = e.materialOverrides[i];
                overrides.push_back(
                    {{"primitive", o.primitive},
                     {"material", material(o.material, p + "/materialOverrides/" +
                                                           std::to_string(i) + "/material")}});
            }
            out["materialOverrides"] = std::move(overrides);
        }
        if (e.light) out["light"] = light(*e.light, p + "/light");
        if (e.camera) out["camera"] = camera(*e.camera, p + "/camera");
        if (e.sky) {
            out["sky"] = {{"exr", e.sky->exrPath},
                          {"intensity", number(e.sky->intensity, p + "/sky/intensity")}};
        }
        if (e.fog) {
            const std::string q = p + "/fog/";
            out["fog"] = {{"scattering", number(e.fog->scattering, q + "scattering")},
                          {"absorption", number(e.fog->absorption, q + "absorption")},
                          {"anisotropy", number(e.fog->anisotropy, q + "anisotropy")},
                          {"heightFalloff", number(e.fog->heightFalloff, q + "heightFalloff")},
                          {"baseHeight", number(e.fog->baseHeight, q + "baseHeight")}};
            if (e.fog->bounds) {
                out["fog"]["bounds"] = {{"min", numbers(e.fog->bounds->min, q + "bounds/min")},
                                        {"max", numbers(e.fog->bounds->max, q + "bounds/max")}};
            }
        }
        if (e.rigidBody) out["rigidBody"] = rigidBody(*e.rigidBody, p + "/rigidBody/");
        if (e.collider) out["collider"] = collider(*e.collider, p + "/collider/");
        if (e.audioSource) out["audioSource"] = audioSource(*e.audioSource, p + "/audioSource/");
        if (e.audioListener) {
            out["audioListener"] =
                json{{"gain", number(e.audioListener->gain, p + "/audioListener/gain")}};
        }
        if (e.hair) {
            const std::string q = p + "/hair/";
            const HairStyle& s = e.hair->style;
            out["hair"] = {
                {"count", e.hair->count},
                {"length", number(e.hair->length, q + "length")},
                {"seed", e.hair->seed},
                {"style",
                 {{"rootRadius", number(s.rootRadius, q + "style/rootRadius")},
                  {"tipRadius", number(s.tipRadius, q + "style/tipRadius")},
                  {"color", {s.color[0], s.color[1], s.color[2]}},
                  {"primaryShift", number(s.primaryShift, q + "style/primaryShift")},
                  {"secondaryShift", number(s.secondaryShift, q + "style/secondaryShift")},
                  {"primaryExponent", number(s.primaryExponent, q + "style/primaryExponent")},
                  {"secondaryExponent",
                   number(s.secondaryExponent, q + "style/secondaryExponent")}}}};
        }
        if (e.atmosphere) {
            const Atmosphere& a = *e.atmosphere;
            const std::string q = p + "/atmosphere/";
            out["atmosphere"] = {
                {"rayleighScattering", numbers(a.rayleighScattering, q + "rayleighScattering")},
                {"rayleighScaleHeight", number(a.rayleighScaleHeight, q + "rayleighScaleHeight")},
                {"mieScattering", number(a.mieScattering, q + "mieScattering")},
                {"mieAbsorption", number(a.mieAbsorption, q + "mieAbsorption")},
                {"mieScaleHeight", number(a.mieScaleHeight, q + "mieScaleHeight")},
                {"mieAnisotropy", number(a.mieAnisotropy, q + "mieAnisotropy")},
                {"ozoneAbsorption", numbers(a.ozoneAbsorption, q + "ozoneAbsorption")},
                {"ozoneCenterHeight", number(a.ozoneCenterHeight, q + "ozoneCenterHeight")},
                {"ozoneWidth", number(a.ozoneWidth, q + "ozoneWidth")},
                {"groundRadius", number(a.groundRadius, q + "groundRadius")},
                {"atmosphereHeight", number(a.atmosphereHeight, q + "atmosphereHeight")},
                {"groundAlbedo", numbers(a.groundAlbedo, q + "groundAlbedo")},
                {"solarIlluminance", number(a.solarIlluminance, q + "solarIlluminance")},
                {"sunAngularDiameter", number(a.sunAngularDiameter, q + "sunAngularDiameter")},
                {"latitude", number(a.latitude, q + "latitude")},
                {"dayOfYear", number(a.dayOfYear, q + "dayOfYear")},
                {"timeOfDay", number(a.timeOfDay, q + "timeOfDay")}};
        }
        if (!e.gameDataJson.empty()) {
            json data = json::parse(e.gameDataJson, nullptr, false);
            if (data.is_discarded() && error.empty()) {
                error = p + "/gameData: not valid JSON text";
            }
            out["gameData"] = std::move(data);
        }
        return out;
    }
};

}  // namespace

std::string sceneToJson(const SceneDocument& scene, std::string& error) {
    Writer writer;
    json entities = json::array();
    for (std::size_t i = 0; i < scene.entities.size(); ++i) {
        entities.push_back(writer.entity(scene.entities[i], "/entities/" + std::to_string(i)));
    }
    error = writer.error;
    if (!error.empty()) return {};
    json document = {
        {"format", kFormatName}, {"version", kSceneFileVersion}, {"entities", std::move(entities)}};
    if (!scene.materialLayers.empty()) {
        json library = json::array();
        for (std::size_t i = 0; i < scene.materialLayers.size(); ++i) {
            library.push_back(
                writer.layer(scene.materialLayers[i], "/materialLayers/" + std::to_string(i)));
        }
        if (!writer.error.empty()) {
            error = writer.error;
            return {};
        }
        document["materialLayers"] = std::move(library);
    }
    if (scene.quality)
        document["quality"] = std::string(nameOf(kQualityLevelNames, *scene.quality));
    if (scene.ambientOcclusion) {
        const SceneAmbientOcclusion& ao = *scene.ambientOcclusion;
        document["ambient_occlusion"] = {
            {"radius", writer.number(ao.radius, "/ambient_occlusion/radius")},
            {"intensity", writer.number(ao.intensity, "/ambient_occlusion/intensity")}};
    }
    // Every chosen render setting under its row's key (render_setting_table.h): a name, or a
    // number the reader reads back bit for bit.
    forEachRenderSetting([&](const auto& row) {
        const auto& choice = scene.settings.*row.choice;
        if (!choice) return;
        const std::string pointer = "/" + std::string(row.sceneKey);
        json value;
        if (!row.names.empty()) {
            value = renderSettingText(row, *choice);
        } else if constexpr (std::is_floating_point_v<std::remove_cvref_t<decltype(*choice)>>) {
            value = writer.number(*choice, pointer);
        } else {
            value = *choice;
        }
        if (!renderSettingAllows(row, *choice)) {
            if (writer.error.empty()) {
                writer.error = pointer + ": " + renderSettingText(row, *choice) + " is not " +
                               renderSettingExpects(row);
            }
            return;
        }
        const SceneKeyPath path = sceneKeyPath(row.sceneKey);
        json& object = path.object.empty() ? document : document[std::string(path.object)];
        object[std::string(path.member)] = std::move(value);
    });
    if (!writer.error.empty()) {
        error = writer.error;
        return {};
    }
    try {
        return document.dump(2) + "\n";
    } catch (const nlohmann::json::exception& e) {  // e.g. a name that is not valid UTF-8
        error = std::string("cannot write JSON: ") + e.what();
        return {};
    }
}

}  // namespace candela::content
