#pragma once
// Test and report support for antialiasing (issue 24): the scenes (a box on a floor under a
// sun, the demo's colonnade, thin posts under a slow pan, a small bright object crossing a dark
// frame), a renderer driven frame by frame, the 4x4 supersampled reference and the measures (edge
// RMSE in the displayed image, motion-compensated flicker, radiance left behind).
#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <vector>

#include "test_scene.h"

namespace candela::render::test {

// Displayed value, [0, 1] per channel, of what the player sees (the LDR target).
inline std::vector<float> displayed(const CapturedFrame& frame) {
    std::vector<float> rgb(size_t(frame.width) * frame.height * 3);
    for (size_t p = 0; p < size_t(frame.width) * frame.height; ++p) {
        for (int c = 0; c < 3; ++c)
            rgb[p * 3 + c] = float(frame.ldrRgba[p * 4 + c]) / 255.0f;
    }
    return rgb;
}

// tonemap.comp on the CPU: exposure, the ACES fit, sRGB encoding.
inline float displayedFromRadiance(float radiance, float ev100) {
    float x = std::min(radiance * exposureFromEv100(ev100), 64.0f);
    float t = std::clamp((x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f), 0.0f, 1.0f);
    return t <= 0.0031308f ? t * 12.92f : 1.055f * std::pow(t, 1.0f / 2.4f) - 0.055f;
}

// The box-on-a-floor scene of the issue: a grey box turned 30 degrees on a light floor under
// a low sun, against a dark sky; every silhouette and the floor's horizon are hard edges.
inline TestScene boxOnFloor(uint32_t width, uint32_t height) {
    TestScene scene;
    scene.width = width;
    scene.height = height;
    content::Material floor = lambertWhite();
    floor.baseColorFactor = {0.8f, 0.8f, 0.8f, 1.0f};
    content::Material box = lambertWhite();
    box.baseColorFactor = {0.15f, 0.12f, 0.1f, 1.0f};
    scene.add(content::makePlane(6.0f), floor);
    glm::mat4 boxWorld = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.5f, 0.0f)) *
                         glm::rotate(glm::mat4(1.0f), glm::radians(30.0f), glm::vec3(0, 1, 0));
    scene.add(content::makeBox({0.5f, 0.5f, 0.5f}), box, boxWorld);
    LightInstance sun;
    sun.light.type = content::LightType::Directional;
    sun.light.lux = 4.0f;
    sun.direction = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.3f));
    scene.lights.push_back(sun);
    scene.lookAt({1.6f, 1.3f, 2.4f}, {0.0f, 0.35f, 0.0f}, {0.0f, 1.0f, 0.0f}, glm::radians(50.0f));
    scene.camera.ev100 = 0.0f;
    return scene;
}

// The demo's colonnade (runtime/src/demo_scene.cpp): square pillars on plinths with capitals,
// 2.8 m apart, under one lintel (the architrave), on a dark floor under a low sun, seen from
// the hall at an angle so the row recedes: long vertical silhouettes, the lintel's horizontal
// edges, thin gaps between distant pillars and their shadows.
inline TestScene colonnade(uint32_t width, uint32_t height) {
    TestScene scene;
    scene.width = width;
    scene.height = height;
    content::Material floor = lambertWhite();
    floor.baseColorFactor = {0.16f, 0.15f, 0.14f, 1.0f};
    content::Material pillar = lambertWhite();
    pillar.baseColorFactor = {0.8f, 0.78f, 0.74f, 1.0f};
    content::Material stone = lambertWhite();
    stone.baseColorFactor = {0.72f, 0.68f, 0.62f, 1.0f};
    constexpr float kPillarHeight = 4.4f, kSpacing = 2.8f;
    constexpr int kPillars = 5;
    scene.add(content::makePlane(12.0f), floor);
    auto at = [](float x, float y, float z) {
        return glm::translate(glm::mat4(1.0f), glm::vec3(x, y, z));
    };
    for (int i = 0; i < kPillars; ++i) {
        const float z = -kSpacing * float(i);
        scene.add(content::makeBox({0.28f, kPillarHeight * 0.5f, 0.28f}), pillar,
                  at(0.0f, kPillarHeight * 0.5f, z));
        scene.add(content::makeBox({0.45f, 0.12f, 0.45f}), stone, at(0.0f, 0.12f, z));
        scene.add(content::makeBox({0.45f, 0.12f, 0.45f}), stone,
                  at(0.0f, kPillarHeight + 0.12f, z));
    }
    const float length = kSpacing * float(kPillars - 1);
    scene.add(content::makeBox({0.45f, 0.25f, 0.5f * length + 0.6f}), stone,
              at(0.0f, kPillarHeight + 0.49f, -0.5f * length));
    LightInstance sun;
    sun.light.type = content::LightType::Directional;
    sun.light.lux = 4.0f;
    sun.direction = glm::normalize(glm::vec3(-0.5f, -0.8f, -0.35f));
    scene.lights.push_back(sun);
    scene.lookAt({4.2f, 1.7f, 3.0f}, {0.0f, 2.6f, -4.5f}, {0.0f, 1.0f, 0.0f}, glm::radians(60.0f));
    scene.camera.ev100 = 0.0f;
    return scene;
}

// Forward MSAA's scene: a glTF BLEND box (alpha 1, so it hides the floor like an opaque one
// but is drawn by the forward pass) turned 30 degrees on a light floor, seen from above so
// the floor fills the frame: the box's silhouette is the only geometric edge, and it belongs
// to forward geometry. The sun casts no shadow (no shadow edge the deferred pass would draw).
inline TestScene blendedBoxFromAbove(uint32_t width, uint32_t height) {
    TestScene scene;
    scene.width = width;
    scene.height = height;
    content::Material floor = lambertWhite();
    floor.baseColorFactor = {0.8f, 0.8f, 0.8f, 1.0f};
    content::Material box = lambertWhite();
    box.baseColorFactor = {0.1f, 0.08f, 0.06f, 1.0f};
    box.alphaMode = content::AlphaMode::Blend;
    scene.add(content::makePlane(8.0f), floor);
    glm::mat4 boxWorld = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.3f, 0.0f)) *
                         glm::rotate(glm::mat4(1.0f), glm::radians(30.0f), glm::vec3(0, 1, 0));
    scene.add(content::makeBox({0.5f, 0.3f, 0.5f}), box, boxWorld);
    LightInstance sun;
    sun.light.type = content::LightType::Directional;
    sun.light.lux = 4.0f;
    sun.direction = glm::normalize(glm::vec3(-0.3f, -1.0f, -0.2f));
    scene.lights.push_back(sun);
    scene.lookAt({0.4f, 3.0f, 0.6f}, {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, glm::radians(45.0f));
    scene.camera.ev100 = 0.0f;
    return scene;
}

// Renders `frames` frames of the same scene with one renderer; returns the last.
inline CapturedFrame renderStatic(GpuContext& context, TestScene& scene, AntiAliasing aa,
                                  uint32_t frames, RendererStats* stats = nullptr,
                                  uint32_t msaaSamples = 1) {
    RendererOptions options;
    options.aa = aa;
    options.msaaSamples = msaaSamples;
    return scene.render(context, options, stats, frames);
}

// How the 16 samples of a reference pixel are combined.
enum class ResolveConvention {
    LinearLight,  // radiance averaged, then exposed and tonemapped (what TAA resolves)
    Displayed,    // each sample tonemapped, the displayed values averaged
};

// The 4x4 supersampled reference: the scene at 4x the size, one sample per pixel, each 4x4
// block combined by `convention` and shown like the engine's output; displayed values in
// [0, 1].
inline std::vector<float> supersampledReference(
    GpuContext& context, TestScene (*make)(uint32_t, uint32_t), uint32_t width, uint32_t height,
    ResolveConvention convention = ResolveConvention::LinearLight) {
    TestScene big = make(width * 4, height * 4);
    CapturedFrame frame = renderStatic(context, big, AntiAliasing::Off, 1);
    std::vector<float> out(size_t(width) * height * 3);
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x) {
            for (int c = 0; c < 3; ++c) {
                double sum = 0.0;
                for (uint32_t sy = 0; sy < 4; ++sy) {
                    for (uint32_t sx = 0; sx < 4; ++sx) {
                        const float radiance = hdrPixel(frame, x * 4 + sx, y * 4 + sy)[c];
                        sum += convention == ResolveConvention::LinearLight
                                   ? radiance
                                   : displayedFromRadiance(radiance, big.camera.ev100);
                    }
                }
                out[(size_t(y) * width + x) * 3 + c] =
                    convention == ResolveConvention::LinearLight
                        ? displayedFromRadiance(float(sum / 16.0), big.camera.ev100)
                        : float(sum / 16.0);
            }
        }
    }
    return out;
}

// Edge pixels: where the reference differs from a 4-neighbour by more than 0.04 in any
// channel (the silhouettes, the horizon, the shadow's edge), away from the border.
inline std::vector<uint8_t> edgeMask(const std::vector<float>& reference, uint32_t width,
                                     uint32_t height) {
    std::vector<uint8_t> mask(size_t(width) * height, 0);
    for (uint32_t y = 1; y + 1 < height; ++y) {
        for (uint32_t x = 1; x + 1 < width; ++x) {
            const size_t p = size_t(y) * width + x;
            const size_t neighbours[] = {p - 1, p + 1, p - width, p + width};
            for (size_t q : neighbours) {
                for (int c = 0; c < 3; ++c) {
                    if (std::abs(reference[p * 3 + c] - reference[q * 3 + c]) > 0.04f) mask[p] = 1;
                }
            }
        }
    }
    return mask;
}

inline double edgeRmse(const std::vector<float>& image, const std::vector<float>& reference,
                       const std::vector<uint8_t>& mask) {
    double sum = 0.0;
    size_t count = 0;
    for (size_t p = 0; p < mask.size(); ++p) {
        if (!mask[p]) continue;
        for (int c = 0; c < 3; ++c) {
            double d = double(image[p * 3 + c]) - reference[p * 3 + c];
            sum += d * d;
            ++count;
        }
    }
    return count ? std::sqrt(sum / double(count)) : 0.0;
}

// Thin posts (about 1.5 pixels wide at 128x64) in front of a lit wall, for the pan test: the
// camera moves along +X, so every static pixel moves by the same screen distance per frame.
inline TestScene thinPosts(uint32_t width, uint32_t height) {
    TestScene scene;
    scene.width = width;
    scene.height = height;
    content::Material wall = lambertWhite();
    wall.baseColorFactor = {0.7f, 0.7f, 0.7f, 1.0f};
    content::Material post = lambertWhite();
    post.baseColorFactor = {0.05f, 0.05f, 0.05f, 1.0f};
    // The wall: a plane turned to face +Z, at z = -0.2 behind the posts.
    scene.add(content::makePlane(20.0f), wall,
              glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -0.2f)) *
                  glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(1, 0, 0)));
    for (int i = -12; i <= 12; ++i) {
        // Slightly different widths and a slight lean so each post crawls differently.
        float halfWidth = 0.012f + 0.002f * float((i + 12) % 3);
        glm::mat4 world =
            glm::translate(glm::mat4(1.0f), glm::vec3(0.137f * float(i), 0.0f, 0.0f)) *
            glm::rotate(glm::mat4(1.0f), glm::radians(2.0f), glm::vec3(0, 0, 1));
        scene.add(content::makeBox({halfWidth, 3.0f, 0.01f}), post, world);
    }
    LightInstance sun;
    sun.light.type = content::LightType::Directional;
    sun.light.lux = 4.0f;
    sun.direction = glm::normalize(glm::vec3(0.2f, -0.3f, -1.0f));
    scene.lights.push_back(sun);
    scene.lookAt({0.0f, 0.0f, 4.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, glm::radians(40.0f));
    scene.camera.ev100 = 0.0f;
    return scene;
}

// The renderer options of a frame sequence with antialiasing `aa` (FrameSequence drives one
// renderer frame by frame with a scene whose draws and camera change).
inline RendererOptions aaOptions(AntiAliasing aa) {
    RendererOptions options;
    options.aa = aa;
    return options;
}

// Mean absolute change of the displayed image between two frames of a pan that moved every
// static pixel `shift` pixels to the left, after moving the previous frame by the same amount
// (linear interpolation); over the pixels at least 4 from the border.
inline double compensatedFlicker(const std::vector<float>& previous,
                                 const std::vector<float>& current, uint32_t width, uint32_t height,
                                 float shift) {
    double sum = 0.0;
    size_t count = 0;
    for (uint32_t y = 4; y + 4 < height; ++y) {
        for (uint32_t x = 4; x + 4 < width; ++x) {
            // current(x) shows what previous showed at x + shift.
            float source = float(x) + shift;
            int x0 = int(std::floor(source));
            float t = source - float(x0);
            for (int c = 0; c < 3; ++c) {
                float a = previous[(size_t(y) * width + x0) * 3 + c];
                float b = previous[(size_t(y) * width + x0 + 1) * 3 + c];
                sum += std::abs(current[(size_t(y) * width + x) * 3 + c] - (a + (b - a) * t));
                ++count;
            }
        }
    }
    return sum / double(count);
}

}  // namespace candela::render::test
