#include "candela/render/atmosphere_transmittance.h"

#include <algorithm>
#include <cmath>

namespace candela::render {

namespace {

glm::dvec3 rgb(const std::array<float, 3>& a) {
    return {a[0], a[1], a[2]};
}

// The same profiles as common/atmosphere.glsl, in metres.
glm::dvec3 extinctionAt(const content::Atmosphere& a, double h) {
    const double rayleigh = std::exp(-h / a.rayleighScaleHeight);
    const double mie = std::exp(-h / a.mieScaleHeight);
    const double ozone =
        std::max(0.0, 1.0 - std::abs(h - a.ozoneCenterHeight) / (0.5 * a.ozoneWidth));
    return rgb(a.rayleighScattering) * rayleigh +
           glm::dvec3(double(a.mieScattering) + double(a.mieAbsorption)) * mie +
           rgb(a.ozoneAbsorption) * ozone;
}

}  // namespace

glm::dvec3 atmosphereTransmittance(const content::Atmosphere& a, double altitude, double cosZenith,
                                   int steps) {
    const double rb = a.groundRadius;
    const double rt = rb + double(a.atmosphereHeight);
    const double r = rb + altitude;
    const double mu = std::clamp(cosZenith, -1.0, 1.0);
    const double discriminant = r * r * (mu * mu - 1.0) + rt * rt;
    const double length = std::max(-r * mu + std::sqrt(std::max(discriminant, 0.0)), 0.0);
    const double dt = length / steps;
    glm::dvec3 depth(0.0);
    for (int i = 0; i < steps; ++i) {
        const double t = (i + 0.5) * dt;
        const double radius = std::sqrt(t * t + 2.0 * r * mu * t + r * r);
        depth += extinctionAt(a, radius - rb) * dt;
    }
    return glm::exp(-depth);
}

glm::dvec3 sunIlluminanceAtGround(const content::Atmosphere& a, double altitude,
                                  double sinElevation) {
    const double r = double(a.groundRadius) + altitude;
    const double mu = std::clamp(sinElevation, -1.0, 1.0);
    const double rb = a.groundRadius;
    if (mu < 0.0 && r * r * (mu * mu - 1.0) + rb * rb >= 0.0) return glm::dvec3(0.0);
    return glm::dvec3(a.solarIlluminance) * atmosphereTransmittance(a, altitude, mu, 4000);
}

double luminanceOf(const glm::dvec3& c) {
    return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}

}  // namespace candela::render
