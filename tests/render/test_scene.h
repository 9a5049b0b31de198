#pragma once
// Test support: small scenes built from procedural meshes, rendered offscreen, and the
// camera math to find the world point behind each pixel.
#include <glm/gtc/matrix_transform.hpp>
#include <optional>
#include <vector>

#include "candela/content/procedural_mesh.h"
#include "offscreen_frame.h"

namespace candela::render::test {

// A Lambert-only material: white, non-metal, Specular 0 -> F0 = 0, and eq. 5's 2% rule
// then zeroes the specular lobe exactly.
inline content::Material lambertWhite() {
    content::Material m;
    m.baseColorFactor = {1.0f, 1.0f, 1.0f, 1.0f};
    m.metallicFactor = 0.0f;
    m.roughnessFactor = 1.0f;
    m.specular = 0.0f;
    return m;
}

struct TestScene {
    content::Model model;
    std::vector<DrawItem> draws;
    std::vector<LightInstance> lights;
    CameraView camera;
    uint32_t width = 128;
    uint32_t height = 128;
    std::shared_ptr<const Environment> environment;  // the sky, when set
    float skyIntensity = 1.0f;

    // One mesh per primitive, each with its own material.
    void add(content::Primitive primitive, const content::Material& material,
             const glm::mat4& world = glm::mat4(1.0f)) {
        primitive.material = int32_t(model.materials.size());
        model.materials.push_back(material);
        content::Mesh mesh;
        mesh.primitives.push_back(std::move(primitive));
        model.meshes.push_back(std::move(mesh));
        worlds.push_back(world);
    }

    void lookAt(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up,
                float verticalFov = glm::radians(60.0f)) {
        camera.view = glm::lookAt(eye, target, up);
        camera.projection = reverseZPerspective(verticalFov, float(width) / float(height), 0.05f);
        camera.nearPlane = 0.05f;
        camera.farPlane = 200.0f;
        camera.position = eye;
    }

    // Uploads the model into `resources` and returns the frame that draws it.
    FrameInputs prepare(SceneResources& resources) {
        const UploadedModel& uploaded = resources.addModel(model);
        draws.clear();
        for (size_t m = 0; m < model.meshes.size(); ++m) {
            draws.push_back({uploaded.firstPrimitiveOfMesh[m], uploaded.firstMaterial + uint32_t(m),
                             worlds[m]});
        }
        FrameInputs inputs;
        inputs.scene.camera = camera;
        inputs.scene.draws = draws;
        inputs.scene.lights = lights;
        inputs.scene.skyIntensity = skyIntensity;
        return inputs;
    }

    // Renders `frames` frames with one renderer; returns the last (stats: of the last).
    CapturedFrame render(GpuContext& context, const RendererOptions& options = {},
                         RendererStats* stats = nullptr, uint32_t frames = 1) {
        SceneResources resources(context);
        resources.setEnvironment(environment);
        FrameInputs inputs = prepare(resources);
        return renderOffscreen(context, inputs, width, height, frames, &resources, options, stats);
    }

    // Where the ray through the centre of pixel (x, y) meets the plane y = planeY.
    std::optional<glm::vec3> pixelOnPlane(uint32_t x, uint32_t y, float planeY = 0.0f) const {
        glm::mat4 inverse = glm::inverse(camera.projection * camera.view);
        glm::vec2 ndc((float(x) + 0.5f) / float(width) * 2.0f - 1.0f,
                      (float(y) + 0.5f) / float(height) * 2.0f - 1.0f);
        glm::vec4 near = inverse * glm::vec4(ndc, 1.0f, 1.0f);
        glm::vec4 far = inverse * glm::vec4(ndc, 0.5f, 1.0f);
        glm::vec3 a = glm::vec3(near) / near.w;
        glm::vec3 b = glm::vec3(far) / far.w;
        glm::vec3 dir = b - a;
        if (std::abs(dir.y) < 1e-9f) return std::nullopt;
        float t = (planeY - a.y) / dir.y;
        if (t <= 0.0f) return std::nullopt;
        return a + dir * t;
    }

private:
    std::vector<glm::mat4> worlds;
};

inline LightInstance pointLight(const glm::vec3& position, float lumens, float radius) {
    LightInstance l;
    l.light.type = content::LightType::Point;
    l.light.lumens = lumens;
    l.light.attenuationRadius = radius;
    l.position = position;
    return l;
}

inline const float* hdrPixel(const CapturedFrame& frame, uint32_t x, uint32_t y) {
    return &frame.hdrRgb[(size_t(y) * frame.width + x) * 3];
}

}  // namespace candela::render::test
