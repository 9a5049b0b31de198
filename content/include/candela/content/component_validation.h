#pragma once
// One set of rules for the values a Light, Camera, Sky, rotation and material emission may
// hold, shared by the scene-file loader, the glTF importer and the editor, so that the editor
// never saves what the loader would then drop.
//
// Values outside their domain are rejected: a negative lumens, lux, colour or radius, an
// attenuation radius of 0, a vertical field of view outside (0, pi), near not in front of far,
// a zero quaternion, an empty sky path, spot cones that are inverted or outside [0, pi/2].
// Finite but physically absurd magnitudes are clamped to the limits below, with a warning,
// so that no product in the shaders can overflow to Inf and turn a frame into NaN.
//
//   ValueProblems problems = validateLight(light);  // may clamp fields of `light`
//   for (const ValueProblem& p : problems) report(p.field, p.message, p.clamped);
//   if (anyRejected(problems)) dropTheLight();
#include <array>
#include <string>
#include <vector>

#include "candela/content/components/atmosphere.h"
#include "candela/content/components/audio_listener.h"
#include "candela/content/components/audio_source.h"
#include "candela/content/components/camera.h"
#include "candela/content/components/collider.h"
#include "candela/content/components/fog.h"
#include "candela/content/components/light.h"
#include "candela/content/components/rigid_body.h"
#include "candela/content/components/sky.h"
#include "candela/content/material.h"

namespace candela::content {

// Far beyond any real lamp (a stadium floodlight is ~1e6 lm), yet small enough that intensity
// x colour x BRDF x exposure stays finite in 32-bit floats.
inline constexpr float kMaxLumens = 1e12f;
inline constexpr float kMaxAreaLightSize = 1e4f;  // metres, a rect light's width or height
// Metres: the smallest rect side or disk radius. The rect's LTC polygon integral loses its
// precision below it (a 0.1 mm rect came out 11x too bright at ultra), and the emitting area
// that divides the lumens underflows further down (a 1e-30 m rect was switched off).
inline constexpr float kMinAreaLightSize = 1e-3f;
inline constexpr float kMaxLux = 1e7f;                 // the sun at noon is ~1.2e5 lux
inline constexpr float kMaxLightColorChannel = 1e3f;   // colour is a multiplier, normally <= 1
inline constexpr float kMaxSkyIntensity = 1e6f;        // multiplies the sky's cd/m^2
inline constexpr float kMaxEmissiveLuminance = 1e10f;  // cd/m^2; the sun's disc is ~1.6e9
// Fog coefficients (1/m): 1e3 already hides everything past a millimetre.
inline constexpr float kMaxFogCoefficient = 1e3f;
// The atmosphere's scattering and absorption coefficients (1/m; Earth's Rayleigh is ~6e-6).
inline constexpr float kMaxAirCoefficient = 1e3f;
// The narrowest perspective camera (0.06 degrees, past any lens), its nearest near plane and
// the smallest orthographic half height: below them the projection overflows.
inline constexpr float kMinVerticalFov = 1e-3f;             // radians
inline constexpr float kMinNearPlane = 1e-5f;               // metres
inline constexpr float kMinOrthographicHalfHeight = 1e-6f;  // metres
inline constexpr float kMaxVolumetricScale = 1e3f;          // multiplies a light's in-scattering
// Rigid bodies: past these a 32-bit float step loses the contact solver (an aircraft carrier
// is 1e8 kg; a rifle bullet flies at 1e3 m/s), and a collider finer than a tenth of a
// millimetre or wider than 100 km is beyond what a game's metre-scale world resolves.
inline constexpr float kMaxBodyMass = 1e9f;          // kg
inline constexpr float kMaxBodySpeed = 1e4f;         // m/s, each velocity component
inline constexpr float kMaxBodyAngularSpeed = 1e3f;  // rad/s, each component
inline constexpr float kMinColliderSize = 1e-4f;     // metres, a radius or half extent
inline constexpr float kMaxColliderSize = 1e5f;      // metres
// Audio: a gain over 1e3 (+60 dB) only clips; a pitch outside 1/64..64 is past what the mixer
// resamples (OpenAL Soft's own limit is 255, its quality gone long before).
inline constexpr float kMaxAudioGain = 1e3f;
inline constexpr float kMinAudioPitch = 1.0f / 64.0f;
inline constexpr float kMaxAudioPitch = 64.0f;
inline constexpr float kMinAudioDistance = 1e-3f;  // metres
inline constexpr float kMaxAudioDistance = 1e6f;   // metres

struct ValueProblem {
    std::string field;     // as the scene file names it: "lumens", "verticalFov", "exr"
    std::string message;   // what is wrong; for a clamp also the value used instead
    bool clamped = false;  // true: clamped and usable; false: rejected
};
using ValueProblems = std::vector<ValueProblem>;

bool anyRejected(const ValueProblems& problems);

ValueProblems validateLight(Light& light);
ValueProblems validateCamera(Camera& camera);
ValueProblems validateSky(Sky& sky);
// Negative or non-finite coefficients, |anisotropy| >= 1 (the phase function has a pole) and a
// negative or non-finite height falloff are rejected.
ValueProblems validateFog(Fog& fog);
// Negative or non-finite coefficients, albedo or illuminance, scale heights and radii that are
// not positive, an anisotropy with |g| >= 1, a sun diameter outside (0, 20] degrees, a latitude
// outside [-90, 90], a day outside [1, 366] and a time of day past 24 hours are rejected.
ValueProblems validateAtmosphere(Atmosphere& atmosphere);
// A unit quaternion x, y, z, w; a zero (or non-finite) one has no orientation.
ValueProblems validateRotation(const std::array<float, 4>& rotation);
// emissiveFactor x emissiveStrength: negative values and luminances over
// kMaxEmissiveLuminance are clamped.
ValueProblems validateEmission(Material& material);
// The factors defined on [0, 1] (metallic, roughness, occlusion strength, cavity, specular,
// subsurface opacity, anisotropy strength, clear coat and its roughness): outside, clamped
// with a warning; NaN refused. Scene files and editor edits share it (issue 44: a cavity of
// 3e38 was clamped by the editor without a word).
ValueProblems validateMaterialFactors(Material& material);
// A dynamic body's mass that is not positive and finite becomes 1 kg; friction below 0,
// restitution and damping outside [0, 1], a non-finite gravity scale and non-finite velocities
// are clamped (velocities to 0), each with a warning naming the field.
ValueProblems validateRigidBody(RigidBody& body);
// A radius, half extent or height that is zero, negative or not finite is rejected (the
// collider has no size); sizes beyond kMinColliderSize..kMaxColliderSize are clamped, and a
// capsule shorter than its two hemispheres becomes a sphere's height (2 radius).
ValueProblems validateCollider(Collider& collider);
// An empty clip path is rejected (there is nothing to play). Gain, pitch, distances and
// rolloff outside their ranges (audio_source.h) are clamped with a warning; NaN takes the
// default; a maxDistance below minDistance becomes minDistance.
ValueProblems validateAudioSource(AudioSource& source);
// A negative or non-finite gain is clamped.
ValueProblems validateAudioListener(AudioListener& listener);
// Texture references against the model's `textureCount` textures: an index past them (a scene
// file's material override naming texture 99) is a warning per slot, named by its key; the
// renderer binds the slot's fallback (white, or a flat normal).
ValueProblems validateMaterialTextures(const Material& material, std::size_t textureCount);

}  // namespace candela::content
