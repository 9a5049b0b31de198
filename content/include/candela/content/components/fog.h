#pragma once
// Fog component: a participating medium filling the scene or a box of it (issue 17, Vos 2014,
// GPU Pro 5, "Volumetric Light Effects in Killzone: Shadow Fall"). Uniform scattering and
// absorption coefficients per metre, optionally thinning with height, and a Henyey-Greenstein phase
// function. In-scattered radiance per metre is sigmaS * density * p(theta) * E, E a light's
// irradiance at the point (render/README.md "Volumetric lighting").
#include <array>
#include <optional>

namespace candela::content {

// An axis-aligned box in world space (metres). A bounded Fog fills only the box: outside it the
// medium neither scatters nor attenuates, as air without dust.
struct FogBounds {
    std::array<float, 3> min{};
    std::array<float, 3> max{};

    bool operator==(const FogBounds&) const = default;
};

struct Fog {
    float scattering = 0.02f;  // sigma_s, 1/m at the base height
    float absorption = 0.0f;   // sigma_a, 1/m at the base height
    float anisotropy = 0.0f;   // Henyey-Greenstein g, in (-1, 1); 0 is isotropic
    // Density exp(-heightFalloff * (y - baseHeight)) (1/m); 0: the same density everywhere.
    float heightFalloff = 0.0f;
    float baseHeight = 0.0f;  // metres, world Y
    // None: the medium fills the whole scene. Set: only this box (min < max on every axis).
    std::optional<FogBounds> bounds;

    bool operator==(const Fog&) const = default;
};

}  // namespace candela::content
