#pragma once
// Test support for ambient occlusion (tests and report rows): a black unit box resting on a
// white floor under a uniform white sky, seen from above at an angle, and a CPU ray trace of
// the floor's cosine-weighted sky visibility to compare the rendered floor against.
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "box_ray.h"
#include "candela/render/environment.h"
#include "test_scene.h"

namespace candela::render::test {

struct VisibilityError {
    uint32_t occludedPixels = 0;  // floor pixels whose true visibility is under 0.9
    double occludedMeanAbs = 0.0;
    double occludedMeanSigned = 0.0;  // rendered - true
    uint32_t openPixels = 0;          // floor pixels whose true visibility is over 0.97
    double openMeanDarkening = 0.0;   // true - rendered, mean
    double openMaxDarkening = 0.0;
};

class BoxOnFloor {
public:
    struct Settings {
        float radius = 1.5f;  // the engine's default (FrameScene::aoRadius)
        float intensity = 1.0f;
        uint32_t slices = AmbientOcclusionSettings{}.slices;
        uint32_t steps = AmbientOcclusionSettings{}.steps;
        uint32_t referenceRays = 128;
    };
    static constexpr glm::vec3 kBoxMin{-0.5f, 0.0f, -0.5f};
    static constexpr glm::vec3 kBoxMax{0.5f, 1.0f, 0.5f};

    // `floor`: white Lambert unless given (the report's specular rows use a glossy one).
    explicit BoxOnFloor(GpuContext& context, uint32_t size = 128,
                        const content::Material& floor = lambertWhite())
        : context_(context) {
        scene_.width = size;
        scene_.height = size;
        content::Material black = lambertWhite();
        black.baseColorFactor = {0.0f, 0.0f, 0.0f, 1.0f};
        scene_.add(content::makePlane(20.0f), floor);
        scene_.add(content::makeBox({0.5f, 0.5f, 0.5f}), black,
                   glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.5f, 0.0f)));
        eye_ = {2.2f, 2.6f, 2.8f};
        scene_.lookAt(eye_, {0.0f, 0.2f, 0.0f}, {0.0f, 1.0f, 0.0f});
        scene_.environment = Environment::uniform(context, 1.0f);
        trueVisibility_.assign(size_t(size) * size, -1.0f);
        for (uint32_t y = 0; y < size; ++y) {
            for (uint32_t x = 0; x < size; ++x) {
                std::optional<glm::vec3> p = scene_.pixelOnPlane(x, y);
                if (!p || boxHidesPixel(*p)) continue;
                trueVisibility_[size_t(y) * size + x] = rayTracedVisibility(*p);
            }
        }
    }

    // The floor's radiance (= visibility: white Lambert floor, white sky of radiance 1).
    CapturedFrame render(AoMode mode, const Settings& settings, RendererStats* stats = nullptr,
                         uint32_t frames = 1, const RendererOptions* given = nullptr) {
        const RendererOptions options = given ? *given : optionsFor(mode, settings);
        SceneResources resources(context_);
        resources.setEnvironment(scene_.environment);
        FrameInputs inputs = scene_.prepare(resources);
        inputs.scene.aoRadius = settings.radius;
        inputs.scene.aoIntensity = settings.intensity;
        return renderOffscreen(context_, inputs, scene_.width, scene_.height, frames, &resources,
                               options, stats);
    }

    // The renderer options render() uses for `mode` and `settings`.
    static RendererOptions optionsFor(AoMode mode, const Settings& settings) {
        RendererOptions options;
        options.ao = mode;
        options.aoSettings.slices = settings.slices;
        options.aoSettings.steps = settings.steps;
        options.aoSettings.referenceRays = settings.referenceRays;
        options.aoSettings.multiBounce = false;  // the occluder is black: no bounce
        return options;
    }

    // Frames from one renderer, so its temporal history carries over: each render() draws the
    // box moved by `boxOffset`, with motion vectors from the previous call's offset.
    class Sequence {
    public:
        Sequence(BoxOnFloor& owner, const RendererOptions& options, const Settings& settings)
            : owner_(owner),
              settings_(settings),
              resources_(owner.context_),
              frames_(owner.context_, owner.scene_.width, owner.scene_.height, options) {
            resources_.setEnvironment(owner.scene_.environment);
        }

        CapturedFrame render(const glm::vec3& boxOffset, RendererStats* stats = nullptr) {
            FrameInputs inputs = owner_.scene_.prepare(resources_);
            inputs.scene.aoRadius = settings_.radius;
            inputs.scene.aoIntensity = settings_.intensity;
            const glm::mat4 shift = glm::translate(glm::mat4(1.0f), boxOffset);
            const glm::mat4 was =
                glm::translate(glm::mat4(1.0f), previousOffset_.value_or(boxOffset));
            // prepare() rebuilt the scene's draws, which inputs.scene.draws views.
            std::vector<DrawItem>& draws = owner_.scene_.draws;
            const glm::mat4 boxWorld = draws[1].world;
            draws[1].world = shift * boxWorld;
            previousWorlds_ = {draws[0].world, was * boxWorld};
            inputs.scene.previousWorlds = previousWorlds_;
            previousOffset_ = boxOffset;
            return frames_.render(inputs, resources_, stats);
        }

    private:
        BoxOnFloor& owner_;
        Settings settings_;
        SceneResources resources_;
        FrameSequence frames_;
        std::optional<glm::vec3> previousOffset_;
        std::vector<glm::mat4> previousWorlds_;
    };

    // The ray-traced visibility at (x, y); negative where the pixel is not open floor or is
    // next to the box's silhouette.
    float trueVisibility(int x, int y) const {
        return floorAwayFromEdges(x, y) ? trueVisibility_[size_t(y) * scene_.width + x] : -1.0f;
    }

    VisibilityError compare(AoMode mode, const Settings& settings) {
        return compare(render(mode, settings));
    }

    // Against the ray trace, over floor pixels not next to the box's silhouette (where the
    // pixel straddles box and floor).
    VisibilityError compare(const CapturedFrame& frame) const {
        VisibilityError e;
        const int size = int(scene_.width);
        for (int y = 0; y < size; ++y) {
            for (int x = 0; x < size; ++x) {
                if (!floorAwayFromEdges(x, y)) continue;
                const double truth = trueVisibility_[size_t(y) * size + x];
                const double rendered = hdrPixel(frame, uint32_t(x), uint32_t(y))[1];
                if (truth < 0.9) {
                    ++e.occludedPixels;
                    e.occludedMeanAbs += std::abs(rendered - truth);
                    e.occludedMeanSigned += rendered - truth;
                } else if (truth > 0.97) {
                    ++e.openPixels;
                    e.openMeanDarkening += truth - rendered;
                    e.openMaxDarkening = std::max(e.openMaxDarkening, truth - rendered);
                }
            }
        }
        if (e.occludedPixels) {
            e.occludedMeanAbs /= e.occludedPixels;
            e.occludedMeanSigned /= e.occludedPixels;
        }
        if (e.openPixels) e.openMeanDarkening /= e.openPixels;
        return e;
    }

private:
    bool floorAwayFromEdges(int x, int y) const {
        const int size = int(scene_.width);
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                const int qx = std::clamp(x + dx, 0, size - 1);
                const int qy = std::clamp(y + dy, 0, size - 1);
                if (trueVisibility_[size_t(qy) * size + qx] < 0.0f) return false;
            }
        }
        return true;
    }

    // Whether the segment from `origin` along `dir` (t in (0, tMax)) meets the box.
    static bool hitsBox(const glm::vec3& origin, const glm::vec3& dir, float tMax) {
        return rayHitsBox(origin, dir, Box{kBoxMin, kBoxMax}, 1e-5f, tMax);
    }

    bool boxHidesPixel(const glm::vec3& floorPoint) const {
        const glm::vec3 d = floorPoint - eye_;
        return hitsBox(eye_, d, 0.9999f) || (floorPoint.x > kBoxMin.x && floorPoint.x < kBoxMax.x &&
                                             floorPoint.z > kBoxMin.z && floorPoint.z < kBoxMax.z);
    }

    // Cosine-weighted visibility of the sky from floor point p: 32 x 32 stratified cosine
    // directions (Malley's method), the fraction that miss the box.
    static float rayTracedVisibility(const glm::vec3& p) {
        constexpr int kSide = 32;
        int escaped = 0;
        for (int i = 0; i < kSide; ++i) {
            for (int j = 0; j < kSide; ++j) {
                const float u = (float(i) + 0.5f) / kSide;
                const float v = (float(j) + 0.5f) / kSide;
                const float r = std::sqrt(u);
                const float phi = 2.0f * std::numbers::pi_v<float> * v;
                const glm::vec3 d(r * std::cos(phi), std::sqrt(std::max(1.0f - u, 0.0f)),
                                  r * std::sin(phi));
                if (!hitsBox(p, d, 1e6f)) ++escaped;
            }
        }
        return float(escaped) / float(kSide * kSide);
    }

    GpuContext& context_;
    TestScene scene_;
    glm::vec3 eye_;
    std::vector<float> trueVisibility_;
};

}  // namespace candela::render::test
