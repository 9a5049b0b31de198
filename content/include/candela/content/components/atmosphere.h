#pragma once
// Atmosphere component: a physically based sky (issue 16; Hillaire 2020, "A Scalable and
// Production Ready Sky and Atmosphere Rendering Technique"). A spherical planet with a shell of
// air: Rayleigh scattering (molecules) and Mie scattering and absorption (aerosols), each
// thinning exponentially with altitude, and an ozone layer that absorbs, with a tent-shaped
// profile. The sky it draws replaces an EXR sky and lights the scene (image-based lighting);
// the scene's first directional light becomes its sun, whose illuminance and colour at the
// ground are the sun outside the atmosphere times the atmosphere's transmittance.
//
// Defaults: Earth's standard atmosphere as Hillaire 2020 (and Bruneton 2017's demo) use it;
// coefficients per metre, heights in metres. render/README.md "Atmosphere" cites the sources.
#include <array>

namespace candela::content {

struct Atmosphere {
    // Rayleigh scattering at sea level (1/m, linear sRGB primaries ~ 680, 550, 440 nm) and the
    // scale height of its exponential density.
    std::array<float, 3> rayleighScattering{5.802e-6f, 13.558e-6f, 33.1e-6f};
    float rayleighScaleHeight = 8000.0f;
    // Mie (aerosols): grey scattering and absorption at sea level (1/m), scale height, and the
    // Cornette-Shanks phase function's asymmetry g in (-1, 1).
    float mieScattering = 3.996e-6f;
    float mieAbsorption = 0.444e-6f;
    float mieScaleHeight = 1200.0f;
    float mieAnisotropy = 0.8f;
    // Ozone absorption at the layer's peak (1/m); density 1 - |h - centre| / (width / 2),
    // clamped to 0, so 0 below 10 km and above 40 km with the defaults.
    std::array<float, 3> ozoneAbsorption{0.650e-6f, 1.881e-6f, 0.085e-6f};
    float ozoneCenterHeight = 25000.0f;
    float ozoneWidth = 30000.0f;
    float groundRadius = 6360000.0f;     // metres: the scene's y = 0 lies on it
    float atmosphereHeight = 100000.0f;  // metres above the ground where the air ends
    std::array<float, 3> groundAlbedo{0.3f, 0.3f, 0.3f};  // lights the multiple scattering
    // The sun outside the atmosphere: its illuminance on a surface facing it, in lux (white in
    // linear sRGB), and its apparent diameter. 128,000 lux: the solar illuminance constant
    // E_sc at the mean Sun-Earth distance (Wikipedia "Sunlight", Calculation: 128 x 10^3 lx;
    // the IES Lighting Handbook's 127,500 lx rounded); 0.545 degrees: the sun's mean apparent
    // diameter (0.527..0.545 over the year).
    float solarIlluminance = 128000.0f;
    float sunAngularDiameter = 0.545f;  // degrees
    // Where the sun stands at a time of day (--time-of-day): latitude in degrees (north
    // positive) and day of the year (1..366). World -Z is north, +X east, +Y up.
    float latitude = 45.0f;
    float dayOfYear = 172.0f;  // the June solstice
    // Hours since local solar midnight, 0..24; negative: the sun keeps the scene light's
    // direction.
    float timeOfDay = -1.0f;

    bool operator==(const Atmosphere&) const = default;
};

}  // namespace candela::content
