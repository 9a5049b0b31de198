#include "candela/runtime/atmosphere_sun.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "candela/render/atmosphere_transmittance.h"

namespace candela::runtime {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// Due south: the azimuth given to a sun whose light points straight down.
constexpr glm::vec3 kDefaultAzimuth{0.0f, 0.0f, 1.0f};

}  // namespace

glm::vec3 sunDirectionAtTime(float latitudeDegrees, float dayOfYear, float hours) {
    const float latitude = glm::radians(latitudeDegrees);
    const float declination =
        glm::radians(-23.44f) * std::cos(2.0f * kPi * (dayOfYear + 10.0f) / 365.0f);
    const float hourAngle = glm::radians(15.0f * (hours - 12.0f));
    const float sinElevation = std::sin(latitude) * std::sin(declination) +
                               std::cos(latitude) * std::cos(declination) * std::cos(hourAngle);
    // East, north and up components of the direction towards the sun.
    const float east = -std::cos(declination) * std::sin(hourAngle);
    const float north = std::cos(latitude) * std::sin(declination) -
                        std::sin(latitude) * std::cos(declination) * std::cos(hourAngle);
    return glm::normalize(glm::vec3(east, sinElevation, -north));
}

void AtmosphereSun::apply(const SunPlacement& placement, render::FrameScene& scene) {
    const content::Atmosphere& atmosphere = *scene.atmosphere;
    lights_.assign(scene.lights.begin(), scene.lights.end());
    auto sun = std::find_if(lights_.begin(), lights_.end(), [](const render::LightInstance& l) {
        return l.light.type == content::LightType::Directional;
    });
    const bool added = sun == lights_.end();
    if (added) {
        render::LightInstance light;
        light.light.type = content::LightType::Directional;
        light.light.castShadows = true;
        light.direction = glm::normalize(glm::vec3(-0.3f, -0.8f, -0.5f));
        lights_.push_back(light);
        sun = lights_.end() - 1;
    }
    glm::vec3 toward = -glm::normalize(sun->direction);
    const std::optional<float> hours = placement.timeOfDayHours ? placement.timeOfDayHours
                                       : atmosphere.timeOfDay >= 0.0f
                                           ? std::optional<float>(atmosphere.timeOfDay)
                                           : std::nullopt;
    if (hours) toward = sunDirectionAtTime(atmosphere.latitude, atmosphere.dayOfYear, *hours);
    if (placement.elevationDegrees) {
        glm::vec3 horizontal(toward.x, 0.0f, toward.z);
        horizontal = glm::length(horizontal) > 1e-4f ? glm::normalize(horizontal) : kDefaultAzimuth;
        const float e = glm::radians(*placement.elevationDegrees);
        toward = horizontal * std::cos(e) + glm::vec3(0.0f, std::sin(e), 0.0f);
    }
    towardSun_ = toward;
    sun->direction = -toward;
    const double altitude = std::max(double(scene.camera.position.y), 0.0);
    illuminance_ = render::sunIlluminanceAtGround(atmosphere, altitude, double(toward.y));
    const double lux = render::luminanceOf(illuminance_);
    sun->light.lux = float(lux);
    if (lux > 0.0) {
        for (int c = 0; c < 3; ++c)
            sun->light.color[c] = float(illuminance_[c] / lux);
    }
    const uint32_t sunIndex = uint32_t(sun - lights_.begin());
    changed_.assign(scene.changedLights.begin(), scene.changedLights.end());
    changed_.push_back(sunIndex);
    scene.lightsRestructured = scene.lightsRestructured || lights_.size() != lastCount_;
    lastCount_ = lights_.size();
    scene.lights = lights_;
    scene.changedLights = changed_;
}

}  // namespace candela::runtime
