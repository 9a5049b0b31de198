#pragma once
// A small lit glTF scene the perturbation tests write, change one parameter of, and render:
// a sphere on a floor, one point light, a camera. Every parameter the perturbations
// touch (light position, roughness, shading model) is a field.
#include <array>
#include <string>

namespace candela::golden::test {

struct LitScene {
    std::array<float, 3> lightPosition{0.6f, 1.3f, 0.9f};  // metres
    // Point-light intensity in candela (glTF's unit); bright enough for the engine's default
    // sunny-16 exposure (EV100 14.6), where mid grey is ~5000 cd/m^2.
    float lightCandela = 40000.0f;
    float lightRange = 20.0f;
    std::array<float, 3> sphereBaseColor{0.8f, 0.35f, 0.2f};
    float sphereRoughness = 0.4f;
    float sphereMetallic = 0.0f;
    // glTF extras.shadingModel: defaultLit, subsurface, legacy or unlit. Legacy gets
    // diffuse = base colour and specular = 0.04 so a swap keeps the albedo.
    std::string sphereShadingModel = "defaultLit";
};

// glTF 2.0 JSON with the geometry embedded as a base64 data URI; the camera looks at the
// sphere from 2.6 m.
std::string litSceneGltf(const LitScene& scene);

}  // namespace candela::golden::test
