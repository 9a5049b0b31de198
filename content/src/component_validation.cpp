#include "candela/content/component_validation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <utility>

#include "candela/content/light_types.h"
#include "candela/content/light_units.h"

namespace candela::content {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

std::string text(float value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", double(value));
    return buffer;
}

void reject(ValueProblems& problems, const char* field, const std::string& message) {
    problems.push_back({field, message, false});
}

// Clamps an absurdly large magnitude (Inf included) down to `limit`, with a warning.
void clampAbove(ValueProblems& problems, const char* field, float& value, float limit,
                const char* unit) {
    if (!(value > limit)) return;
    problems.push_back({field,
                        text(value) + unit + " is beyond the limit of " + text(limit) + unit +
                            "; using " + text(limit) + unit,
                        true});
    value = limit;
}

// Positive values below `limit` become `limit`, with a clamped problem (0 and below are the
// caller's to reject).
void clampBelow(ValueProblems& problems, const char* field, float& value, float limit,
                const char* unit) {
    if (!(value > 0 && value < limit)) return;
    problems.push_back({field,
                        text(value) + unit + " is below the limit of " + text(limit) + unit +
                            "; using " + text(limit) + unit,
                        true});
    value = limit;
}

bool finite(float value) {
    return std::isfinite(value);
}

}  // namespace

bool anyRejected(const ValueProblems& problems) {
    return std::any_of(problems.begin(), problems.end(),
                       [](const ValueProblem& p) { return !p.clamped; });
}

// Each field by its rule in the light type table (content/light_types.h); cone angles
// together, for the types that use them.
ValueProblems validateLight(Light& light) {
    ValueProblems problems;
    for (const LightFieldInfo& f : kLightFieldTable) {
        const std::string unit = f.unit.empty() ? "" : " " + std::string(f.unit);
        switch (f.rule) {
            case LightFieldRule::ColorChannels: {
                std::array<float, 3>& channels = light.*f.channels;
                for (float c : channels) {
                    if (std::isnan(c) || c < 0) {
                        reject(problems, f.name, "colour channels must be finite and not negative");
                        break;
                    }
                }
                for (float& c : channels)
                    clampAbove(problems, f.name, c, f.max, unit.c_str());
                break;
            }
            case LightFieldRule::NonNegative: {
                float& value = light.*f.scalar;
                if (std::isnan(value) || value < 0) {
                    reject(problems, f.name, "must not be negative, got " + text(value));
                }
                clampAbove(problems, f.name, value, f.max, unit.c_str());
                break;
            }
            case LightFieldRule::Positive: {
                float& value = light.*f.scalar;
                if (!(value > 0)) {
                    reject(problems, f.name, "must be greater than 0, got " + text(value));
                } else {
                    clampAbove(problems, f.name, value, f.max, unit.c_str());
                }
                break;
            }
            case LightFieldRule::FiniteNonNegative: {
                float& value = light.*f.scalar;
                if (!finite(value) || value < 0) {
                    reject(problems, f.name, "must be finite and not negative, got " + text(value));
                } else if (f.max > 0) {
                    clampAbove(problems, f.name, value, f.max, unit.c_str());
                }
                break;
            }
            case LightFieldRule::ConeAngle:
                break;
        }
    }
    // An area light needs an area: its luminance is lumens / (pi area). Width and height are
    // checked above for every type; a disk's radius may be 0 elsewhere (a point light).
    if (usesField(light.type, LightField::SourceRadius) && isAreaLight(light.type) &&
        !(light.sourceRadius > 0)) {
        reject(problems, "sourceRadius",
               "a disk light needs a radius greater than 0 (zero area), got " +
                   text(light.sourceRadius));
    }
    // Emitters too small to integrate (kMinAreaLightSize) are made that small: they still shed
    // their lumens, as the point-like light they are.
    if (isAreaLight(light.type)) {
        for (LightField field : {LightField::Width, LightField::Height, LightField::SourceRadius}) {
            if (!usesField(light.type, field)) continue;
            const LightFieldInfo& f = kLightFieldTable[std::size_t(field)];
            clampBelow(problems, f.name, light.*f.scalar, kMinAreaLightSize, " m");
        }
    }
    if (usesField(light.type, LightField::OuterConeAngle)) {
        const float inner = light.innerConeAngle;
        const float outer = light.outerConeAngle;
        if (!(outer > 0 && outer <= kPi / 2)) {
            reject(problems, "outerConeAngle", "must be in (0, pi/2] radians, got " + text(outer));
        } else if (!(inner >= 0)) {
            reject(problems, "innerConeAngle", "must not be negative, got " + text(inner));
        } else if (inner > outer) {
            reject(problems, "innerConeAngle",
                   "the inner cone (" + text(inner) + ") is wider than the outer cone (" +
                       text(outer) + "): inverted spot cones");
        }
    }
    return problems;
}

ValueProblems validateCamera(Camera& camera) {
    ValueProblems problems;
    // Past these limits the projection's scale (1 / tan(fov / 2), 1 / half height) or its
    // near-plane terms overflow single precision and the whole frame turns to NaN (issue 44:
    // a field of view of 1e-45 rad).
    if (camera.projection == Projection::Perspective) {
        if (!(camera.verticalFov > 0 && camera.verticalFov < kPi)) {
            reject(problems, "verticalFov",
                   "must be between 0 and pi radians (exclusive), got " + text(camera.verticalFov));
        }
        clampBelow(problems, "verticalFov", camera.verticalFov, kMinVerticalFov, " rad");
        clampBelow(problems, "nearPlane", camera.nearPlane, kMinNearPlane, " m");
    } else if (!(camera.orthographicHalfHeight > 0) || !finite(camera.orthographicHalfHeight)) {
        reject(problems, "orthographicHalfHeight",
               "must be greater than 0, got " + text(camera.orthographicHalfHeight));
    } else {
        clampBelow(problems, "orthographicHalfHeight", camera.orthographicHalfHeight,
                   kMinOrthographicHalfHeight, " m");
    }
    const bool orthographic = camera.projection == Projection::Orthographic;
    if (!finite(camera.nearPlane) || camera.nearPlane < 0 ||
        (!orthographic && camera.nearPlane == 0)) {
        reject(problems, "nearPlane",
               std::string(orthographic ? "must not be negative" : "must be greater than 0") +
                   ", got " + text(camera.nearPlane));
    } else if (!(camera.farPlane > camera.nearPlane)) {
        reject(problems, "farPlane",
               "must be beyond nearPlane (" + text(camera.nearPlane) + "), got " +
                   text(camera.farPlane));
    }
    if (camera.exposureMode == ExposureMode::Physical) {
        for (auto [field, value] :
             {std::pair{"aperture", camera.aperture},
              std::pair{"shutterSeconds", camera.shutterSeconds}, std::pair{"iso", camera.iso}}) {
            if (!(value > 0) || !finite(value)) {
                reject(problems, field, "must be greater than 0, got " + text(value));
            }
        }
    }
    return problems;
}

ValueProblems validateSky(Sky& sky) {
    ValueProblems problems;
    if (sky.exrPath.empty()) reject(problems, "exr", "the sky needs an OpenEXR file path");
    if (std::isnan(sky.intensity) || sky.intensity < 0) {
        reject(problems, "intensity", "must not be negative, got " + text(sky.intensity));
    }
    clampAbove(problems, "intensity", sky.intensity, kMaxSkyIntensity, "");
    return problems;
}

ValueProblems validateFog(Fog& fog) {
    ValueProblems problems;
    for (auto [field, value] :
         {std::pair{"scattering", &fog.scattering}, std::pair{"absorption", &fog.absorption}}) {
        if (std::isnan(*value) || *value < 0) {
            reject(problems, field, "must not be negative (1/m), got " + text(*value));
        } else {
            clampAbove(problems, field, *value, kMaxFogCoefficient, " 1/m");
        }
    }
    if (!finite(fog.anisotropy) || !(std::fabs(fog.anisotropy) < 1.0f)) {
        reject(problems, "anisotropy",
               "the Henyey-Greenstein g must lie strictly between -1 and 1, got " +
                   text(fog.anisotropy));
    }
    if (!finite(fog.heightFalloff) || fog.heightFalloff < 0) {
        reject(problems, "heightFalloff",
               "must be finite and not negative (1/m), got " + text(fog.heightFalloff));
    }
    if (!finite(fog.baseHeight)) {
        reject(problems, "baseHeight", "must be finite, got " + text(fog.baseHeight));
    }
    if (fog.bounds) {
        static constexpr const char* kAxes[] = {"x", "y", "z"};
        for (int axis = 0; axis < 3; ++axis) {
            const float lo = fog.bounds->min[axis];
            const float hi = fog.bounds->max[axis];
            if (!finite(lo) || !finite(hi) || !(lo < hi)) {
                reject(problems, "bounds",
                       std::string("min must be below max on every axis (metres), got ") +
                           kAxes[axis] + " " + text(lo) + " to " + text(hi));
                break;
            }
        }
    }
    return problems;
}

ValueProblems validateAtmosphere(Atmosphere& a) {
    ValueProblems problems;
    auto notNegative = [&](const char* field, float value, const char* unit) {
        if (!finite(value) || value < 0) {
            reject(problems, field,
                   std::string("must be finite and not negative") + unit + ", got " + text(value));
        }
    };
    auto positive = [&](const char* field, float value, const char* unit) {
        if (!finite(value) || !(value > 0)) {
            reject(problems, field,
                   std::string("must be finite and positive") + unit + ", got " + text(value));
        }
    };
    for (auto [field, rgb] : {std::pair{"rayleighScattering", &a.rayleighScattering},
                              std::pair{"ozoneAbsorption", &a.ozoneAbsorption},
                              std::pair{"groundAlbedo", &a.groundAlbedo}}) {
        for (float c : *rgb) {
            if (!finite(c) || c < 0) {
                reject(problems, field, "channels must be finite and not negative, got " + text(c));
                break;
            }
        }
    }
    for (float c : a.groundAlbedo) {
        if (c > 1.0f) {
            reject(problems, "groundAlbedo", "channels must not exceed 1, got " + text(c));
            break;
        }
    }
    notNegative("mieScattering", a.mieScattering, " (1/m)");
    notNegative("mieAbsorption", a.mieAbsorption, " (1/m)");
    positive("rayleighScaleHeight", a.rayleighScaleHeight, " (m)");
    positive("mieScaleHeight", a.mieScaleHeight, " (m)");
    notNegative("ozoneCenterHeight", a.ozoneCenterHeight, " (m)");
    positive("ozoneWidth", a.ozoneWidth, " (m)");
    positive("groundRadius", a.groundRadius, " (m)");
    positive("atmosphereHeight", a.atmosphereHeight, " (m)");
    notNegative("solarIlluminance", a.solarIlluminance, " (lux)");
    if (!finite(a.mieAnisotropy) || !(std::fabs(a.mieAnisotropy) < 1.0f)) {
        reject(problems, "mieAnisotropy",
               "the phase function's g must lie strictly between -1 and 1, got " +
                   text(a.mieAnisotropy));
    }
    if (!finite(a.sunAngularDiameter) || !(a.sunAngularDiameter > 0) ||
        a.sunAngularDiameter > 20.0f) {
        reject(problems, "sunAngularDiameter",
               "must lie in (0, 20] degrees, got " + text(a.sunAngularDiameter));
    }
    if (!finite(a.latitude) || std::fabs(a.latitude) > 90.0f) {
        reject(problems, "latitude", "must lie in [-90, 90] degrees, got " + text(a.latitude));
    }
    if (!finite(a.dayOfYear) || a.dayOfYear < 1.0f || a.dayOfYear > 366.0f) {
        reject(problems, "dayOfYear", "must lie in [1, 366], got " + text(a.dayOfYear));
    }
    if (!finite(a.timeOfDay) || a.timeOfDay > 24.0f) {
        reject(problems, "timeOfDay",
               "must be hours in [0, 24] (negative: keep the light's direction), got " +
                   text(a.timeOfDay));
    }
    // Past these the tables' optical depths (coefficient x path length through the air)
    // overflow to Inf and the sky turns to NaN; 1e3 1/m is already opaque within a millimetre.
    for (auto [field, rgb] : {std::pair{"rayleighScattering", &a.rayleighScattering},
                              std::pair{"ozoneAbsorption", &a.ozoneAbsorption}}) {
        const float largest = std::max({(*rgb)[0], (*rgb)[1], (*rgb)[2]});
        if (largest > kMaxAirCoefficient) {
            problems.push_back({field,
                                "channels up to " + text(largest) +
                                    " 1/m are beyond the limit of " + text(kMaxAirCoefficient) +
                                    " 1/m; using " + text(kMaxAirCoefficient) + " 1/m for those",
                                true});
            for (float& c : *rgb)
                c = std::min(c, kMaxAirCoefficient);
        }
    }
    clampAbove(problems, "mieScattering", a.mieScattering, kMaxAirCoefficient, " 1/m");
    clampAbove(problems, "mieAbsorption", a.mieAbsorption, kMaxAirCoefficient, " 1/m");
    // Past these the single-precision shaders lose the planet (radii in km keep 7 digits).
    clampAbove(problems, "groundRadius", a.groundRadius, 1e9f, " m");
    clampAbove(problems, "atmosphereHeight", a.atmosphereHeight, 1e7f, " m");
    clampAbove(problems, "solarIlluminance", a.solarIlluminance, kMaxLux, " lux");
    return problems;
}

ValueProblems validateRotation(const std::array<float, 4>& q) {
    ValueProblems problems;
    const float lengthSq = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
    // Said as it is: a 3e38 component overflowed the length and was called "a zero quaternion".
    if (!finite(lengthSq)) {
        reject(problems, "rotation",
               "its length is not a finite number (components too large or not finite): not "
               "a rotation");
    } else if (!(lengthSq > 1e-12f)) {
        reject(problems, "rotation", "a zero quaternion is not a rotation");
    }
    return problems;
}

ValueProblems validateMaterialFactors(Material& material) {
    struct UnitFactor {
        const char* name;
        float Material::*field;
    };
    static constexpr UnitFactor kUnitFactors[] = {
        {"metallicFactor", &Material::metallicFactor},
        {"roughnessFactor", &Material::roughnessFactor},
        {"occlusionStrength", &Material::occlusionStrength},
        {"cavity", &Material::cavity},
        {"specular", &Material::specular},
        {"subsurfaceOpacity", &Material::subsurfaceOpacity},
        {"anisotropyStrength", &Material::anisotropyStrength},
        {"clearcoatFactor", &Material::clearcoatFactor},
        {"clearcoatRoughnessFactor", &Material::clearcoatRoughnessFactor},
    };
    ValueProblems problems;
    for (const UnitFactor& f : kUnitFactors) {
        float& value = material.*f.field;
        if (std::isnan(value)) {
            reject(problems, f.name, "must be a number from 0 to 1, got NaN");
        } else if (value < 0.0f || value > 1.0f) {
            const float clamped = std::clamp(value, 0.0f, 1.0f);
            problems.push_back({f.name,
                                std::string(f.name) + " of material '" + material.name + "' " +
                                    text(value) + " is outside [0, 1]; clamped to " + text(clamped),
                                true});
            value = clamped;
        }
    }
    return problems;
}

ValueProblems validateEmission(Material& material) {
    ValueProblems problems;
    for (float& c : material.emissiveFactor) {
        if (std::isnan(c) || c < 0) {
            problems.push_back({"emissiveFactor", "negative emission; using 0", true});
            c = 0;
        }
        clampAbove(problems, "emissiveFactor", c, kMaxEmissiveLuminance, "");
    }
    if (std::isnan(material.emissiveStrength) || material.emissiveStrength < 0) {
        problems.push_back({"emissiveStrength", "negative emission; using 0", true});
        material.emissiveStrength = 0;
    }
    const float brightest = std::max(
        {material.emissiveFactor[0], material.emissiveFactor[1], material.emissiveFactor[2]});
    // Compared as a division so that the product itself never overflows.
    if (brightest > 0 && material.emissiveStrength > kMaxEmissiveLuminance / brightest) {
        const float limit = kMaxEmissiveLuminance / brightest;
        problems.push_back({"emissiveStrength",
                            "emissiveFactor x emissiveStrength is beyond the limit of " +
                                text(kMaxEmissiveLuminance) + " cd/m^2; using strength " +
                                text(limit),
                            true});
        material.emissiveStrength = limit;
    }
    return problems;
}

ValueProblems validateRigidBody(RigidBody& body) {
    ValueProblems problems;
    const auto clampTo = [&](const char* field, float& value, float lo, float hi,
                             const char* unit) {
        if (value >= lo && value <= hi) return;
        const float used = std::isnan(value) ? lo : std::clamp(value, lo, hi);
        problems.push_back({field,
                            text(value) + unit + " is outside " + text(lo) + ".." + text(hi) +
                                unit + "; using " + text(used) + unit,
                            true});
        value = used;
    };
    if (body.type == BodyType::Dynamic && !(body.mass > 0 && finite(body.mass))) {
        problems.push_back(
            {"mass", "must be positive and finite (kg), got " + text(body.mass) + "; using 1 kg",
             true});
        body.mass = 1.0f;
    }
    clampAbove(problems, "mass", body.mass, kMaxBodyMass, " kg");
    clampTo("friction", body.friction, 0.0f, 1e3f, "");
    clampTo("restitution", body.restitution, 0.0f, 1.0f, "");
    clampTo("linearDamping", body.linearDamping, 0.0f, 1.0f, "");
    clampTo("angularDamping", body.angularDamping, 0.0f, 1.0f, "");
    if (!finite(body.gravityScale)) {
        problems.push_back(
            {"gravityScale", "must be finite, got " + text(body.gravityScale) + "; using 1", true});
        body.gravityScale = 1.0f;
    }
    const auto velocity = [&](const char* field, ecs::Vec3& v, float limit, const char* unit) {
        if (!finite(v.x) || !finite(v.y) || !finite(v.z)) {
            problems.push_back({field, "must be finite; using 0", true});
            v = {};
            return;
        }
        for (float* c : {&v.x, &v.y, &v.z})
            clampTo(field, *c, -limit, limit, unit);
    };
    velocity("linearVelocity", body.linearVelocity, kMaxBodySpeed, " m/s");
    velocity("angularVelocity", body.angularVelocity, kMaxBodyAngularSpeed, " rad/s");
    return problems;
}

ValueProblems validateCollider(Collider& collider) {
    ValueProblems problems;
    const auto size = [&](const char* field, float& value) {
        if (!(value > 0) || !finite(value)) {
            reject(problems, field, "must be positive and finite (metres), got " + text(value));
            return;
        }
        clampBelow(problems, field, value, kMinColliderSize, " m");
        clampAbove(problems, field, value, kMaxColliderSize, " m");
    };
    if (collider.radius) size("radius", *collider.radius);
    if (collider.halfExtents) {
        for (float* c :
             {&collider.halfExtents->x, &collider.halfExtents->y, &collider.halfExtents->z}) {
            size("halfExtents", *c);
        }
    }
    if (collider.height) size("height", *collider.height);
    if (collider.shape == ColliderShape::Capsule && !anyRejected(problems)) {
        const float radius = collider.radius.value_or(kDefaultColliderRadius);
        const float height = collider.height.value_or(kDefaultCapsuleHeight);
        if (height < 2 * radius) {
            problems.push_back({"height",
                                text(height) + " m is less than the two hemispheres (" +
                                    text(2 * radius) + " m); using " + text(2 * radius) + " m",
                                true});
            collider.height = 2 * radius;
        }
    }
    return problems;
}

namespace {

// Clamps `value` into [lo, hi] with a warning naming the field; NaN takes `fallback`.
void clampAudio(ValueProblems& problems, const char* field, float& value, float lo, float hi,
                float fallback, const char* unit) {
    if (value >= lo && value <= hi) return;
    const float used = std::isnan(value) ? fallback : std::clamp(value, lo, hi);
    problems.push_back({field,
                        text(value) + unit + " is outside " + text(lo) + ".." + text(hi) + unit +
                            "; using " + text(used) + unit,
                        true});
    value = used;
}

}  // namespace

ValueProblems validateAudioSource(AudioSource& source) {
    ValueProblems problems;
    if (source.clip.empty()) reject(problems, "clip", "is empty: a source needs a WAV or Ogg file");
    clampAudio(problems, "gain", source.gain, 0.0f, kMaxAudioGain, 1.0f, "");
    clampAudio(problems, "pitch", source.pitch, kMinAudioPitch, kMaxAudioPitch, 1.0f, "");
    clampAudio(problems, "minDistance", source.minDistance, kMinAudioDistance, kMaxAudioDistance,
               1.0f, " m");
    clampAudio(problems, "maxDistance", source.maxDistance, source.minDistance, kMaxAudioDistance,
               std::max(source.minDistance, 100.0f), " m");
    clampAudio(problems, "rolloff", source.rolloff, 0.0f, 1e3f, 1.0f, "");
    return problems;
}

ValueProblems validateAudioListener(AudioListener& listener) {
    ValueProblems problems;
    clampAudio(problems, "gain", listener.gain, 0.0f, kMaxAudioGain, 1.0f, "");
    return problems;
}

ValueProblems validateMaterialTextures(const Material& material, std::size_t textureCount) {
    ValueProblems problems;
    auto check = [&](const std::string& field, const TextureRef& ref) {
        if (!ref.present() || std::size_t(ref.texture) < textureCount) return;
        problems.push_back({field,
                            "texture " + std::to_string(ref.texture) +
                                " is not one of the model's " + std::to_string(textureCount) +
                                " textures; the slot uses its fallback",
                            true});
    };
    static constexpr std::pair<const char*, TextureRef Material::*> kSlots[] = {
        {"baseColorTexture", &Material::baseColorTexture},
        {"metallicRoughnessTexture", &Material::metallicRoughnessTexture},
        {"normalTexture", &Material::normalTexture},
        {"occlusionTexture", &Material::occlusionTexture},
        {"emissiveTexture", &Material::emissiveTexture},
        {"specularTexture", &Material::specularTexture},
        {"specularColorTexture", &Material::specularColorTexture},
        {"anisotropyTexture", &Material::anisotropyTexture},
        {"clearcoatTexture", &Material::clearcoatTexture},
        {"clearcoatRoughnessTexture", &Material::clearcoatRoughnessTexture},
        {"clearcoatNormalTexture", &Material::clearcoatNormalTexture},
    };
    for (const auto& [name, member] : kSlots)
        check(name, material.*member);
    const MaterialLayering& layering = material.layering;
    if (layering.used() && layering.maskSource == LayerMaskSource::Texture) {
        check("layerMask/texture", layering.maskTexture);
    }
    for (std::size_t i = 0; i < layering.layers.size(); ++i) {
        const std::string layer = "layers/" + std::to_string(i) + "/";
        check(layer + "baseColorTexture", layering.layers[i].baseColorTexture);
        check(layer + "metallicRoughnessTexture", layering.layers[i].metallicRoughnessTexture);
        check(layer + "normalTexture", layering.layers[i].normalTexture);
    }
    return problems;
}

}  // namespace candela::content
