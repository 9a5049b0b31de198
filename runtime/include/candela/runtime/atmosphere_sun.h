#pragma once
// The atmosphere's sun in a frame (issue 16, render/README.md "Atmosphere"): the scene's first
// directional light becomes the sun. It keeps its direction unless --sun-elevation (the same
// azimuth at that elevation) or a time of day (--time-of-day, else the component's timeOfDay)
// places it; its illuminance and colour are the atmosphere's solar illuminance outside the
// atmosphere times the transmittance towards the sun at the viewer's altitude
// (render::sunIlluminanceAtGround), so no number is set by hand. A scene without a directional
// light gets one (casting shadows).
#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "candela/content/components/atmosphere.h"
#include "candela/render/frame_scene.h"

namespace candela::runtime {

struct SunPlacement {
    std::optional<float> elevationDegrees;  // --sun-elevation
    std::optional<float> timeOfDayHours;    // --time-of-day (over the component's timeOfDay)
};

// The unit vector towards the sun at local solar time `hours` (0..24) for a latitude (degrees)
// and day of the year: declination -23.44 deg cos(2 pi (day + 10) / 365), hour angle
// 15 deg per hour from noon. World -Z is north, +X east, +Y up.
glm::vec3 sunDirectionAtTime(float latitudeDegrees, float dayOfYear, float hours);

class AtmosphereSun {
public:
    // Rewrites `scene.lights` (and its change list) to a copy held here with the sun placed
    // and lit; `scene.atmosphere` must be set.
    void apply(const SunPlacement& placement, render::FrameScene& scene);

    // The sun of the last apply: towards it, and its illuminance per linear sRGB channel (lux).
    glm::vec3 towardSun() const { return towardSun_; }
    glm::dvec3 illuminance() const { return illuminance_; }

private:
    std::vector<render::LightInstance> lights_;
    std::vector<uint32_t> changed_;
    size_t lastCount_ = 0;
    glm::vec3 towardSun_{0.0f, 1.0f, 0.0f};
    glm::dvec3 illuminance_{0.0};
};

}  // namespace candela::runtime
