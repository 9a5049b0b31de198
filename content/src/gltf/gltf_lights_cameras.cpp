// KHR_lights_punctual lights -> engine Light components (photometric units, SPEC.md), and
// glTF cameras -> engine Camera components.
#include <algorithm>
#include <filesystem>
#include <numbers>

#include "candela/content/component_validation.h"
#include "candela/content/light_texture.h"
#include "candela/content/light_types.h"
#include "candela/content/light_units.h"
#include "gltf_context.h"
#include "gltf_values.h"

namespace candela::content::gltf {
namespace {

NamedLight convertLight(Context& context, const tinygltf::Light& source,
                        const std::string& element) {
    NamedLight named;
    named.name = source.name;
    Light& light = named.light;
    // The glTF type names of the light type table (content/light_types.h).
    const auto row = std::find_if(
        kLightTypeTable.begin(), kLightTypeTable.end(),
        [&](const LightTypeInfo& t) { return t.gltfType && source.type == t.gltfType; });
    if (row != kLightTypeTable.end())
        light.type = row->type;
    else
        context.error(element, "type '" + source.type + "' is unknown; treated as point");
    // Engine extension (issue 15): extras.shape "rect" or "disk" makes a point or spot light a
    // one-sided area light facing the node's -Z.
    if (const tinygltf::Value* shape = member(source.extras, "shape")) {
        const std::string name = shape->IsString() ? shape->Get<std::string>() : std::string();
        if (name == "rect" || name == "disk") {
            light.type = name == "rect" ? LightType::Rect : LightType::Disk;
        } else {
            context.error(element + ".extras.shape",
                          "must be \"rect\" or \"disk\"; the light stays " + source.type);
        }
    }
    const bool inLux = lightTypeInfo(light.type).power == LightPower::Lux;

    if (!source.color.empty() && !copyFactors(source.color, light.color)) {
        context.warning(element, "color is not 3 finite numbers; using white");
    }
    for (float& c : light.color)
        c = std::max(c, 0.0f);
    float intensity = 1;
    if (!toFiniteFloat(source.intensity, intensity) || intensity < 0) {
        context.warning(element, "intensity is negative or not finite; using 1");
        intensity = 1;
    }
    // Clamped before the candela -> lumens conversion, which would overflow to Inf.
    const float maxIntensity = inLux ? kMaxLux : candelaFromLumens(kMaxLumens);
    if (intensity > maxIntensity) {
        const char* unit = inLux ? " lux" : " cd";
        context.warning(element, "intensity " + std::to_string(intensity) + unit +
                                     " is beyond the limit of " + std::to_string(maxIntensity) +
                                     unit + "; clamped");
        intensity = maxIntensity;
    }
    if (inLux) {
        light.lux = intensity;  // glTF: lux for directional lights
    } else if (isAreaLight(light.type)) {
        // On-axis intensity of a Lambertian one-sided emitter: I = L A, power = pi L A.
        light.lumens = std::numbers::pi_v<float> * intensity;
    } else {
        light.lumens = lumensFromCandela(intensity);  // glTF: candela for point and spot
    }

    float range = 0;
    if (toFiniteFloat(source.range, range) && range > 0) {
        light.attenuationRadius = range;  // glTF's range uses the same window (SPEC.md eq. 9)
        named.rangeWasGiven = true;
    } else {
        const float brightest = std::max({light.color[0], light.color[1], light.color[2]});
        light.attenuationRadius = attenuationRadiusForIntensity(intensity, brightest);
    }

    if (usesField(light.type, LightField::OuterConeAngle)) {
        float inner = 0;
        float outer = std::numbers::pi_v<float> / 4;
        toFiniteFloat(source.spot.innerConeAngle, inner);
        toFiniteFloat(source.spot.outerConeAngle, outer);
        outer = std::clamp(outer, 0.0f, std::numbers::pi_v<float> / 2);
        inner = std::clamp(inner, 0.0f, outer);
        light.innerConeAngle = inner;
        light.outerConeAngle = outer;
    }

    // Engine extension: the fields the light type table marks as glTF extras (sphere and
    // tube lights; the tube lies along the node's local X axis).
    bool badShape = false;
    for (const LightFieldInfo& f : kLightFieldTable) {
        if (!f.gltfExtra || !member(source.extras, f.name)) continue;
        float v = 0;
        if (readNumber(source.extras, f.name, v) && v >= 0) {
            light.*f.scalar = v;
        } else if (isAreaLight(light.type) && usesField(light.type, f.field)) {
            context.error(element + ".extras." + f.name,
                          "must be a finite number > 0 for an area light");
            badShape = true;
        } else {
            context.warning(element + ".extras",
                            std::string(f.name) + " must be a finite number >= 0; ignored");
        }
    }
    // Engine extension (issue 15): extras.texture, a PNG or JPEG file relative to the glTF
    // file, is the emissive image of a rect light. Unreadable: an error naming the file and
    // the light, and the rect stays untextured.
    if (const tinygltf::Value* texture = member(source.extras, "texture")) {
        const std::string where = element + ".extras.texture";
        if (light.type != LightType::Rect) {
            context.warning(where,
                            "only a rect light (extras.shape \"rect\") has a texture; "
                            "ignored");
        } else if (!texture->IsString() || texture->Get<std::string>().empty()) {
            context.error(where,
                          "must be a file name (a PNG or JPEG image); the rect is "
                          "untextured");
        } else {
            const std::string name = texture->Get<std::string>();
            const std::filesystem::path file =
                std::filesystem::path(context.file).parent_path() / name;
            std::string problem;
            auto image = loadLightTexture(file, problem);
            const bool loaded = image != nullptr;
            light.texture = registerLightTexture(name, std::move(image));
            if (!loaded) {
                context.error(where, "light '" + source.name + "': cannot use " + file.string() +
                                         ": " + problem + "; the rect is untextured");
            }
        }
    }
    // Engine extension: extras.castShadows (bool), else the type's default.
    light.castShadows = lightTypeInfo(light.type).castsShadowsByDefault;
    if (const tinygltf::Value* cast = member(source.extras, kCastShadowsKey)) {
        if (cast->IsBool()) {
            light.castShadows = cast->Get<bool>();
        } else {
            context.warning(element + ".extras",
                            std::string(kCastShadowsKey) + " must be true or false; ignored");
        }
    }
    // The rules the scene loader and the editor share; what is left to catch here is clamps
    // (colour), as the values above were already made valid.
    const ValueProblems problems = validateLight(light);
    for (const ValueProblem& problem : problems) {
        context.warning(element, problem.field + ": " + problem.message);
    }
    // Extras can still be wrong for an area light (zero area, negative or NaN width): it is
    // skipped, i.e. kept (nodes refer to it by index) but emitting nothing.
    if (isAreaLight(light.type) && (badShape || anyRejected(problems))) {
        context.error(element, "area light with an invalid shape; skipped (emits nothing)");
        light.lumens = 0.0f;
    }
    return named;
}

NamedCamera convertCamera(Context& context, const tinygltf::Camera& source,
                          const std::string& element) {
    NamedCamera named;
    named.name = source.name;
    Camera& camera = named.camera;
    auto positive = [&](const char* what, double in, float& out) {
        float v = 0;
        if (toFiniteFloat(in, v) && v > 0)
            out = v;
        else
            context.warning(element, std::string(what) +
                                         " must be a finite number > 0; "
                                         "using the engine default");
    };
    if (source.type == "orthographic") {
        camera.projection = Projection::Orthographic;
        positive("orthographic.ymag", source.orthographic.ymag, camera.orthographicHalfHeight);
        float znear = 0;  // orthographic znear may be 0
        if (toFiniteFloat(source.orthographic.znear, znear) && znear >= 0) camera.nearPlane = znear;
        positive("orthographic.zfar", source.orthographic.zfar, camera.farPlane);
    } else {
        if (source.type != "perspective") {
            context.warning(element, "type '" + source.type + "' is unknown; using perspective");
        }
        positive("perspective.yfov", source.perspective.yfov, camera.verticalFov);
        camera.verticalFov = std::min(camera.verticalFov, std::numbers::pi_v<float> * 0.999f);
        positive("perspective.znear", source.perspective.znear, camera.nearPlane);
        // No zfar means an infinite projection; the engine keeps its default far plane, which
        // only bounds the clusters under reverse-Z.
        if (source.perspective.zfar > 0) {
            positive("perspective.zfar", source.perspective.zfar, camera.farPlane);
        }
    }
    if (camera.farPlane <= camera.nearPlane) {
        context.warning(element, "zfar is not beyond znear; far plane moved out");
        camera.farPlane = std::max(camera.nearPlane * 1000.0f, 1.0f);
    }
    return named;
}

}  // namespace

void convertLightsAndCameras(Context& context) {
    for (std::size_t i = 0; i < context.document.lights.size(); ++i) {
        context.model.lights.push_back(
            convertLight(context, context.document.lights[i],
                         "extensions.KHR_lights_punctual.lights[" + std::to_string(i) + "]"));
    }
    for (std::size_t i = 0; i < context.document.cameras.size(); ++i) {
        context.model.cameras.push_back(
            convertCamera(context, context.document.cameras[i], elementName("cameras", i)));
    }
}

}  // namespace candela::content::gltf
