#pragma once
// The atmosphere's transmittance on the CPU, in double precision: a direct numerical integral
// of the density profiles (content/components/atmosphere.h) along a ray to the top of the
// atmosphere. The runtime sets the sun light's illuminance and colour from it, and the tests
// measure the shaders' transmittance table against it.
//
//   glm::dvec3 lux = sunIlluminanceAtGround(atmosphere, 0.0, std::sin(elevation));
#include <glm/glm.hpp>

#include "candela/content/components/atmosphere.h"

namespace candela::render {

// exp(-optical depth) from `altitude` metres above the ground along a ray whose zenith angle
// has cosine `cosZenith`, to the top of the atmosphere; the ground is ignored (as in the
// shaders' table). Midpoint rule with `steps` samples (the default is far past convergence).
glm::dvec3 atmosphereTransmittance(const content::Atmosphere& atmosphere, double altitude,
                                   double cosZenith, int steps = 20000);

// The sun's illuminance (lux) per linear sRGB channel on a surface facing it at `altitude`
// metres, for a sun `sinElevation` above the horizontal: the atmosphere's solar illuminance
// (white) times the transmittance; 0 once the planet hides the sun's centre.
glm::dvec3 sunIlluminanceAtGround(const content::Atmosphere& atmosphere, double altitude,
                                  double sinElevation);

// Photometric illuminance of a linear sRGB triple (Rec. 709 luminance weights).
double luminanceOf(const glm::dvec3& rgb);

}  // namespace candela::render
