#pragma once
// Test support for screen-space reflections (tests and report rows): a mirror floor (white
// metal, roughness 0) under an emissive box floating above it, no sky and no light, seen from
// below the box's bottom so the faces its reflection shows are on screen too. A CPU ray trace
// of the same scene says, per pixel, whether the floor there reflects the box.
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "box_ray.h"
#include "test_scene.h"

namespace candela::render::test {

class MirrorUnderBox {
public:
    enum class Truth : int8_t {
        NotFloor,  // the box itself, or no floor behind the pixel
        Box,       // floor whose mirror ray meets the box
        Black,     // floor whose mirror ray escapes
    };
    static constexpr glm::vec3 kBoxMin{-0.5f, 1.0f, -5.0f};
    static constexpr glm::vec3 kBoxMax{0.5f, 1.6f, -4.0f};
    static constexpr float kFloorHalfExtent = 10.0f;
    static constexpr float kEmission = 4.0f;  // the box's emissive strength

    MirrorUnderBox(uint32_t width, uint32_t height, float floorRoughness = 0.0f) {
        scene_.width = width;
        scene_.height = height;
        content::Material mirror;
        mirror.baseColorFactor = {1.0f, 1.0f, 1.0f, 1.0f};
        mirror.metallicFactor = 1.0f;
        mirror.roughnessFactor = floorRoughness;
        scene_.add(content::makePlane(kFloorHalfExtent), mirror);
        content::Material glow;
        glow.shadingModel = content::ShadingModel::Unlit;
        glow.baseColorFactor = {0.0f, 0.0f, 0.0f, 1.0f};
        glow.emissiveFactor = {1.0f, 1.0f, 1.0f};
        glow.emissiveStrength = kEmission;
        const glm::vec3 centre = (kBoxMin + kBoxMax) * 0.5f;
        const glm::vec3 half = (kBoxMax - kBoxMin) * 0.5f;
        scene_.add(content::makeBox({half.x, half.y, half.z}), glow,
                   glm::translate(glm::mat4(1.0f), centre));
        eye_ = {0.3f, 0.2f, 0.0f};
        scene_.lookAt(eye_, {0.0f, 0.3f, -4.5f}, {0.0f, 1.0f, 0.0f});
        truth_.resize(size_t(width) * height, Truth::NotFloor);
        for (uint32_t y = 0; y < height; ++y) {
            for (uint32_t x = 0; x < width; ++x)
                truth_[size_t(y) * width + x] = traceTruth(x, y);
        }
    }

    TestScene& scene() { return scene_; }
    Truth truth(int x, int y) const { return truth_[size_t(y) * scene_.width + size_t(x)]; }
    // The truth at (x, y) where its 8 neighbours agree (so ±1 pixel edges are left out).
    std::optional<Truth> settledTruth(int x, int y) const {
        const Truth t = truth(x, y);
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                const int qx = x + dx, qy = y + dy;
                if (qx < 0 || qy < 0 || qx >= int(scene_.width) || qy >= int(scene_.height)) {
                    return std::nullopt;
                }
                if (truth(qx, qy) != t) return std::nullopt;
            }
        }
        return t;
    }

    // The nearest t > 0 at which the ray meets the box.
    static std::optional<float> hitBox(const glm::vec3& origin, const glm::vec3& dir) {
        return rayBoxEntry(origin, dir, Box{kBoxMin, kBoxMax}, 1e-5f, 1e30f);
    }

private:
    Truth traceTruth(uint32_t x, uint32_t y) const {
        std::optional<glm::vec3> p = scene_.pixelOnPlane(x, y);
        if (!p || std::abs(p->x) > kFloorHalfExtent || std::abs(p->z) > kFloorHalfExtent) {
            return Truth::NotFloor;
        }
        const glm::vec3 toFloor = *p - eye_;
        const std::optional<float> boxFirst = hitBox(eye_, toFloor);
        if (boxFirst && *boxFirst < 1.0f) return Truth::NotFloor;
        const glm::vec3 d = glm::normalize(toFloor);
        const glm::vec3 r{d.x, -d.y, d.z};  // mirrored in the floor (normal +y)
        return hitBox(*p, r) ? Truth::Box : Truth::Black;
    }

    TestScene scene_;
    glm::vec3 eye_;
    std::vector<Truth> truth_;
};

// What a rendered mirror frame shows against the ray trace.
struct MirrorComparison {
    uint32_t boxPixels = 0;         // settled floor pixels that should show the box
    uint32_t boxPixelsWrong = 0;    // ... whose radiance is off the box's by more than 2%
    uint32_t blackPixels = 0;       // settled floor pixels that should be black
    uint32_t blackPixelsWrong = 0;  // ... over 1% of the box's radiance
    double worstBoxError = 0.0;     // relative, over the box pixels
    double boxRadiance = 0.0;       // the box as the frame shows it (its brightest pixel)
    bool finite = true;             // no NaN or Inf anywhere
};

inline MirrorComparison compareMirror(const MirrorUnderBox& m, const CapturedFrame& frame) {
    MirrorComparison c;
    for (uint32_t y = 0; y < frame.height; ++y) {
        for (uint32_t x = 0; x < frame.width; ++x) {
            const float* p = hdrPixel(frame, x, y);
            for (int k = 0; k < 3; ++k)
                c.finite &= std::isfinite(p[k]);
            c.boxRadiance = std::max(c.boxRadiance, double(p[1]));
        }
    }
    for (int y = 0; y < int(frame.height); ++y) {
        for (int x = 0; x < int(frame.width); ++x) {
            const std::optional<MirrorUnderBox::Truth> t = m.settledTruth(x, y);
            if (!t || *t == MirrorUnderBox::Truth::NotFloor) continue;
            const double g = hdrPixel(frame, uint32_t(x), uint32_t(y))[1];
            if (*t == MirrorUnderBox::Truth::Box) {
                ++c.boxPixels;
                const double error = std::abs(g - c.boxRadiance) / c.boxRadiance;
                c.worstBoxError = std::max(c.worstBoxError, error);
                if (error > 0.02) ++c.boxPixelsWrong;
            } else {
                ++c.blackPixels;
                if (g > 0.01 * c.boxRadiance) ++c.blackPixelsWrong;
            }
        }
    }
    return c;
}

}  // namespace candela::render::test
