#pragma once
// Test support for sky occlusion (tests and report rows): a closed room of boxes (four walls
// and a roof with a 1 m skylight) on a white floor under a uniform white sky, and a CPU ray
// trace of the floor's cosine-weighted sky visibility to compare the rendered floor against.
#include <glm/glm.hpp>

#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "box_ray.h"
#include "candela/render/environment.h"
#include "test_scene.h"

namespace candela::render::test {

struct SkyRoomError {
    uint32_t pixels = 0;
    double meanAbs = 0.0;       // |rendered - ray traced| over the room's floor
    double meanTruth = 0.0;     // the ray-traced visibility's mean there
    double meanRendered = 0.0;  // the rendered one's
};

class SkyRoom {
public:
    using Box = test::Box;
    static constexpr float kInner = 2.0f;     // the room's floor spans [-2, 2]^2
    static constexpr float kWall = 0.2f;      // wall and roof thickness
    static constexpr float kHeight = 2.5f;    // the roof's underside
    static constexpr float kSkylight = 0.5f;  // the hole spans [-0.5, 0.5]^2

    // `inside`: the camera under the roof looking down at the floor; else outside, looking
    // away from the room at open ground.
    SkyRoom(GpuContext& context, bool inside, uint32_t size = 96) : context_(context) {
        scene_.width = size;
        scene_.height = size;
        const float o = kInner + kWall;
        boxes_ = {
            {{-o, 0, -o}, {o, kHeight, -kInner}},  // walls
            {{-o, 0, kInner}, {o, kHeight, o}},
            {{-o, 0, -kInner}, {-kInner, kHeight, kInner}},
            {{kInner, 0, -kInner}, {o, kHeight, kInner}},
            // the roof around the skylight
            {{-o, kHeight, -o}, {o, kHeight + kWall, -kSkylight}},
            {{-o, kHeight, kSkylight}, {o, kHeight + kWall, o}},
            {{-o, kHeight, -kSkylight}, {-kSkylight, kHeight + kWall, kSkylight}},
            {{kSkylight, kHeight, -kSkylight}, {o, kHeight + kWall, kSkylight}},
        };
        content::Material grey = lambertWhite();
        grey.baseColorFactor = {0.0f, 0.0f, 0.0f, 1.0f};  // no bounce to model
        scene_.add(content::makePlane(20.0f), lambertWhite());
        for (const Box& b : boxes_) {
            const glm::vec3 half = 0.5f * (b.hi - b.lo);
            scene_.add(content::makeBox({half.x, half.y, half.z}), grey,
                       glm::translate(glm::mat4(1.0f), 0.5f * (b.lo + b.hi)));
        }
        if (inside) {
            scene_.lookAt({0.0f, 2.3f, 1.8f}, {0.0f, 0.0f, -0.4f}, {0.0f, 1.0f, 0.0f},
                          glm::radians(80.0f));
        } else {
            scene_.lookAt({0.0f, 2.0f, 4.0f}, {0.0f, 0.0f, 9.0f}, {0.0f, 1.0f, 0.0f});
        }
        scene_.environment = Environment::uniform(context, 1.0f);
    }

    CapturedFrame render(SkyOcclusionMode mode, RendererStats* stats = nullptr) {
        RendererOptions options;
        options.skyOcclusion = mode;
        return scene_.render(context_, options, stats);
    }

    // Cosine-weighted share of the upper hemisphere that sees the sky from floor point p
    // (n x n stratified rays).
    double rayTracedVisibility(const glm::vec3& p, uint32_t n = 32) const {
        uint32_t open = 0;
        for (uint32_t i = 0; i < n; ++i) {
            for (uint32_t j = 0; j < n; ++j) {
                const double u = (i + 0.5) / n, v = (j + 0.5) / n;
                const double r = std::sqrt(u), phi = 2.0 * std::numbers::pi * v;
                const glm::vec3 d(float(r * std::cos(phi)), float(std::sqrt(1.0 - u)),
                                  float(r * std::sin(phi)));
                open += blocked(p, d) ? 0 : 1;
            }
        }
        return double(open) / double(n * n);
    }

    // The rendered floor (radiance = visibility) against the ray trace over the room's floor,
    // every `stride`-th pixel, away from the walls; against another frame instead when given.
    SkyRoomError compareInside(const CapturedFrame& frame, uint32_t stride = 3,
                               const CapturedFrame* against = nullptr) const {
        SkyRoomError e;
        for (uint32_t y = 0; y < scene_.height; y += stride) {
            for (uint32_t x = 0; x < scene_.width; x += stride) {
                const std::optional<glm::vec3> p = scene_.pixelOnPlane(x, y);
                if (!p || std::abs(p->x) > kInner - 0.1f || std::abs(p->z) > kInner - 0.1f) {
                    continue;
                }
                const double truth =
                    against ? double(hdrPixel(*against, x, y)[1]) : rayTracedVisibility(*p);
                const double rendered = hdrPixel(frame, x, y)[1];
                ++e.pixels;
                e.meanAbs += std::abs(rendered - truth);
                e.meanTruth += truth;
                e.meanRendered += rendered;
            }
        }
        if (e.pixels) {
            e.meanAbs /= e.pixels;
            e.meanTruth /= e.pixels;
            e.meanRendered /= e.pixels;
        }
        return e;
    }

    // Whether any box, grown by `margin` metres, lies in direction d from floor point p.
    bool blocked(const glm::vec3& p, const glm::vec3& d, float margin = 0.0f) const {
        for (const Box& b : boxes_) {
            const Box grown{b.lo - glm::vec3(margin), b.hi + glm::vec3(margin)};
            if (rayHitsBox(p + glm::vec3(0, 1e-4f, 0), d, grown, 0.0f, 1e30f)) return true;
        }
        return false;
    }

    const TestScene& scene() const { return scene_; }

private:
    GpuContext& context_;
    TestScene scene_;
    std::vector<Box> boxes_;
};

}  // namespace candela::render::test
