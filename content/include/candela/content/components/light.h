#pragma once
// Light component: photometric units as SPEC.md "Units and conventions" states.
#include <array>
#include <cstdint>

namespace candela::content {

// Rect and Disk (issue 15) are one-sided area emitters facing the node's -Z.
enum class LightType : std::uint8_t { Point, Spot, Directional, Rect, Disk };

// How an area light (rect, disk) or a sphere or tube light is shaded: the renderer's default (its
// --area-lights), or a per-light override ("quality" in scene files): Drobot's representative
// point (2014, GPU Pro 5, "Physically Based Area Lights") or LTC.
enum class AreaLightQuality : std::uint8_t { Default, Representative, Ltc };

// How a rect or disk light spreads its power ("emission" in scene files): Lambertian (the same
// luminance lumens / (pi area) in every direction), or Drobot's constant-intensity light (every
// element radiates the same intensity in every direction in front of it: lumens / (2 pi area) cd
// per square metre), shaded by Drobot's pre-integrated diffuse and specular factors
// (area_light_constant_intensity.glsl).
enum class AreaLightEmission : std::uint8_t { Lambertian, ConstantIntensity };

struct Light {
    LightType type = LightType::Point;
    std::array<float, 3> color{1.0f, 1.0f, 1.0f};  // linear RGB, multiplies the photometric value
    float lumens = 800.0f;  // luminous power; point/spot: intensity = lumens / (4 pi) cd,
                            // rect/disk: luminance = lumens / (pi area) cd/m^2 (Lambertian)
    float lux = 10.0f;      // directional illuminance
    float attenuationRadius = 10.0f;    // metres; eq. 9 window reaches zero here
    float sourceRadius = 0.0f;          // metres; > 0 makes a sphere light (eq. 10-14); disk radius
    float width = 1.0f;                 // metres, rect only: along the node's local +X
    float height = 1.0f;                // metres, rect only: along the node's local +Y
    float sourceLength = 0.0f;          // metres; > 0 makes a tube along local +X (eq. 16-20)
    float innerConeAngle = 0.0f;        // radians, spot only
    float outerConeAngle = 0.7853982f;  // radians, spot only
    // Scales this light's in-scattering in a Fog medium (artist control, Vos 2014, GPU Pro 5,
    // "Volumetric Light Effects in Killzone: Shadow Fall"); 0: the light lights no fog. Surfaces
    // are lit the same whatever it is.
    float volumetric = 1.0f;
    // Renders a shadow map for this light. Scene files and glTF default it per type
    // (LightTypeInfo::castsShadowsByDefault: directional yes, local lights no); code that builds
    // a Light gets no shadows unless it asks.
    bool castShadows = false;
    AreaLightQuality quality = AreaLightQuality::Default;        // rect, disk, sphere, tube
    AreaLightEmission emission = AreaLightEmission::Lambertian;  // rect, disk
    // Rect only: an emissive image on the light (a screen, a window; issue 15): an id into
    // content/light_texture.h's table (the file as the scene file's "texture" or glTF's
    // extras.texture names it, and the decoded image), 0 for none. An id keeps Light trivially
    // copyable (byte-compared change checks). The image modulates the luminance and is scaled so
    // that its average luminance is the light's Lambertian luminance: lumens = average
    // luminance x pi x area whatever the image.
    std::uint32_t texture = 0;
};

// A point or spot light without a size: the class the renderer shades with its cheapest code
// (lights.glsl's isPlainLocalLight is the same rule on the GPU). NaN sizes count as none.
inline bool isPlainPunctualLight(const Light& light) {
    return (light.type == LightType::Point || light.type == LightType::Spot) &&
           !(light.sourceRadius > 0.0f) && !(light.sourceLength > 0.0f);
}

}  // namespace candela::content
