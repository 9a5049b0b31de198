#pragma once
// The rasterised per-light volumes' draws (Vos 2014, GPU Pro 5, "Volumetric Light Effects in
// Killzone: Shadow Fall": each light renders its volume, a sphere for a point light, a cone for a
// spot, the whole screen for the sun, and here a hemisphere for a rect or disk light, which lights
// only the half-space in front of it; render/README.md "Volumetric lighting"). Each frame the CPU
// sorts the lights that scatter into groups, each drawn with one instanced draw of its proxy mesh
// (light_proxy_mesh.glsl), the light index per instance, so a light costs the GPU only the pixels
// its proxy covers and the CPU no draw call. Lights whose volume misses the view get no instance. A
// proxy the camera is outside of draws its front faces tested against the scene's depth (a volume
// behind the surfaces costs no fragments); one that holds the camera or reaches the near plane
// draws its back faces untested.
//
// Instance list: the directional lights first (the full-screen pass marches them), then each
// draw's lights, in light order within a draw.
#include <cstdint>
#include <span>
#include <vector>

#include "candela/render/frame_scene.h"

namespace candela::render {

// Matches light_proxy_mesh.glsl.
// Hemisphere: rect and disk lights, which emit into the half-space in front of them only.
enum class LightProxyKind : uint32_t { Sphere = 0, Cone = 1, Hemisphere = 2 };
constexpr uint32_t kSphereProxyVertices = 8 * 6 * 6;  // 8 x 6 quads, two triangles each
constexpr uint32_t kConeProxyVertices = 12 * 2 * 3;   // 12 sides and 12 cap triangles
// The sphere's upper 8 x 3 quads and an 8-triangle cap.
constexpr uint32_t kHemisphereProxyVertices = 8 * 3 * 6 + 8 * 3;
// How far the proxy meshes reach past the volume they enclose (light_proxy_mesh.glsl): the
// sphere's faces sit at cos(pi / 8) cos(pi / 6) of the radius from its centre at the least.
float sphereProxyScale();

struct LightProxyDraw {
    LightProxyKind kind = LightProxyKind::Sphere;
    bool areaLights = false;   // rect and disk lights (the SPEC_MEDIUM_AREA_LIGHTS variant)
    bool holdsCamera = false;  // back faces, no depth test
    uint32_t firstInstance = 0, instanceCount = 0;
};

struct LightProxies {
    std::vector<uint32_t> instances;    // light indices (the layout at the top)
    uint32_t fullScreen = 0;            // directional lights at the list's head
    std::vector<LightProxyDraw> draws;  // non-empty groups only
};

// The distance from the camera to its near plane's corners.
float nearPlaneReach(const CameraView& camera);

// Whether the camera may be inside a proxy of bounding sphere (centre, radius) or the near plane
// may cut it: the camera's distance to it is within its radius plus the near plane's corner
// distance (`nearReach`).
bool proxyHoldsCamera(const glm::vec3& centre, float radius, const CameraView& camera);

// The draws of the lights whose `scales` entry is positive, for a width x height frame.
LightProxies buildLightProxies(std::span<const LightInstance> lights, std::span<const float> scales,
                               const CameraView& camera, uint32_t width, uint32_t height);

}  // namespace candela::render
