#pragma once
// Test support (render_wire_tests, candela-report's wire rows): a horizontal unlit emissive
// wire across a 64x64 view at a chosen depth, and the radiance summed down each column.
#include <algorithm>
#include <cmath>
#include <vector>

#include "test_scene.h"

namespace candela::render::test::wires {

constexpr uint32_t kSize = 64;
constexpr float kFov = glm::radians(60.0f);
constexpr float kRadius = 0.05f;    // metres
constexpr float kEmission = 40.0f;  // cd/m^2

// A camera at the origin looking down -Z; a horizontal wire across the whole view at view
// depth `depth`, `height` metres above the axis.
struct WireScene {
    candela::content::Wire wire;
    candela::content::Material material;
    std::vector<WireDraw> draws;
    CameraView camera;

    WireScene() {
        camera.view = glm::mat4(1.0f);
        camera.projection = reverseZPerspective(kFov, 1.0f, 0.05f);
        camera.nearPlane = 0.05f;
        material.shadingModel = candela::content::ShadingModel::Unlit;
        material.emissiveFactor = {1.0f, 1.0f, 1.0f};
        material.emissiveStrength = kEmission;
        wire.radius = kRadius;
        wire.segments = {0, 1};
    }

    // `slope`: the wire's rise per unit of x (0: horizontal).
    FrameInputs place(float depth, float height, float slope = 0.0f) {
        // Far wider than the view at any depth used here.
        wire.positions = {{-1000.0f, height - 1000.0f * slope, -depth},
                          {1000.0f, height + 1000.0f * slope, -depth}};
        draws = {{&wire, &material, glm::mat4(1.0f)}};
        FrameInputs inputs;
        inputs.scene.camera = camera;
        inputs.scene.wires = draws;
        return inputs;
    }
};

// The wire's width in pixels at view depth `depth`.
inline float widthPixels(float depth) {
    const float pixelsPerMetre = float(kSize) / (2.0f * depth * std::tan(kFov / 2.0f));
    return 2.0f * kRadius * pixelsPerMetre;
}

inline float depthForWidth(float pixels) {
    return 2.0f * kRadius * float(kSize) / (2.0f * std::tan(kFov / 2.0f) * pixels);
}

inline std::vector<double> columnSums(const CapturedFrame& frame) {
    std::vector<double> sums(frame.width, 0.0);
    for (uint32_t y = 0; y < frame.height; ++y) {
        for (uint32_t x = 0; x < frame.width; ++x)
            sums[x] += hdrPixel(frame, x, y)[0];
    }
    return sums;
}

// The largest |column sum / expected - 1| over the image.
inline double worstColumnError(const CapturedFrame& frame, double expected) {
    double worst = 0.0;
    for (double sum : columnSums(frame))
        worst = std::max(worst, std::abs(sum / expected - 1.0));
    return worst;
}

}  // namespace candela::render::test::wires
