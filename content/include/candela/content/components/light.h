#pragma once
// Light component: photometric units as SPEC.md "Units and conventions" states.
#include <array>
#include <cstdint>

namespace candela::content {

enum class LightType : std::uint8_t { Point, Spot, Directional };

struct Light {
    LightType type = LightType::Point;
    std::array<float, 3> color{1.0f, 1.0f, 1.0f};  // linear RGB, multiplies the photometric value
    float lumens = 800.0f;              // point/spot luminous power; intensity = lumens / (4 pi) cd
    float lux = 10.0f;                  // directional illuminance
    float attenuationRadius = 10.0f;    // metres; eq. 9 window reaches zero here
    float sourceRadius = 0.0f;          // metres; > 0 makes a sphere light (eq. 10-14)
    float sourceLength = 0.0f;          // metres; > 0 makes a tube along local +X (eq. 16-20)
    float innerConeAngle = 0.0f;        // radians, spot only
    float outerConeAngle = 0.7853982f;  // radians, spot only
    // Scales this light's in-scattering in a Fog medium (artist control, seed 004 §3); 0: the
    // light lights no fog. Surfaces are lit the same whatever it is.
    float volumetric = 1.0f;
    // Renders a shadow map for this light. Scene files and glTF default it per type
    // (LightTypeInfo::castsShadowsByDefault: directional yes, local lights no); code that builds
    // a Light gets no shadows unless it asks.
    bool castShadows = false;
};

}  // namespace candela::content
