#pragma once
// The atmosphere as the shaders read it (common/atmosphere.glsl AtmosphereParameters): the
// component's metres and 1/m turned into kilometres and 1/km, packed into six vec4.
#include <glm/glm.hpp>
#include <numbers>

#include "candela/content/components/atmosphere.h"

namespace candela::render {

struct GpuAtmosphere {
    glm::vec4 rayleigh;       // scattering (1/km), scale height (km)
    glm::vec4 mie;            // scattering (1/km), scale height (km)
    glm::vec4 mieAbsorption;  // absorption (1/km), anisotropy
    glm::vec4 ozone;          // absorption at the peak (1/km), centre height (km)
    glm::vec4 ground;         // albedo, ozone half width (km)
    glm::vec4 radii;          // bottom, top (km), sun angular radius (rad), solar lux
};

inline GpuAtmosphere gpuAtmosphere(const content::Atmosphere& a) {
    auto perKm = [](const std::array<float, 3>& c) {
        return glm::vec3(c[0], c[1], c[2]) * 1000.0f;
    };
    const float km = 1e-3f;
    GpuAtmosphere g;
    g.rayleigh = glm::vec4(perKm(a.rayleighScattering), a.rayleighScaleHeight * km);
    g.mie = glm::vec4(glm::vec3(a.mieScattering * 1000.0f), a.mieScaleHeight * km);
    g.mieAbsorption = glm::vec4(glm::vec3(a.mieAbsorption * 1000.0f), a.mieAnisotropy);
    g.ozone = glm::vec4(perKm(a.ozoneAbsorption), a.ozoneCenterHeight * km);
    g.ground = glm::vec4(a.groundAlbedo[0], a.groundAlbedo[1], a.groundAlbedo[2],
                         0.5f * a.ozoneWidth * km);
    const float bottom = a.groundRadius * km;
    g.radii = glm::vec4(bottom, bottom + a.atmosphereHeight * km,
                        0.5f * a.sunAngularDiameter * std::numbers::pi_v<float> / 180.0f,
                        a.solarIlluminance);
    return g;
}

}  // namespace candela::render
