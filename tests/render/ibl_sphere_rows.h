#pragma once
// The scene the IBL accuracy test and the speed-against-error report compare modes on: two rows
// of six spheres, roughness 0 .. 1 left to right, metal on top (base colour 0.95, 0.93, 0.88),
// a grey dielectric below (0.5, Specular 0.5), lit only by the sky.
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <vector>

#include "candela/render/environment.h"
#include "test_scene.h"

namespace candela::render::test {

struct SphereRows {
    static constexpr float kRadius = 0.45f;
    TestScene scene;
    std::vector<glm::vec3> centres;  // 0..5 metal, 6..11 dielectric
    std::vector<float> roughness;
    std::vector<bool> metallic;
};

inline SphereRows sphereRows(std::shared_ptr<const Environment> sky, uint32_t width,
                             uint32_t height) {
    SphereRows rows;
    rows.scene.width = width;
    rows.scene.height = height;
    for (int row = 0; row < 2; ++row) {
        for (int i = 0; i < 6; ++i) {
            const bool metal = row == 0;
            content::Material m;
            m.baseColorFactor = metal ? std::array<float, 4>{0.95f, 0.93f, 0.88f, 1.0f}
                                      : std::array<float, 4>{0.5f, 0.5f, 0.5f, 1.0f};
            m.metallicFactor = metal ? 1.0f : 0.0f;
            m.roughnessFactor = float(i) / 5.0f;
            glm::vec3 centre((float(i) - 2.5f) * 1.2f, metal ? 0.6f : -0.6f, 0.0f);
            rows.scene.add(content::makeSphere(SphereRows::kRadius, 96, 48), m,
                           glm::translate(glm::mat4(1.0f), centre));
            rows.centres.push_back(centre);
            rows.roughness.push_back(m.roughnessFactor);
            rows.metallic.push_back(metal);
        }
    }
    rows.scene.lookAt({0.0f, 0.0f, 4.5f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f},
                      glm::radians(50.0f));
    rows.scene.environment = std::move(sky);
    return rows;
}

// The sphere the ray through pixel (x, y) meets inside 95% of its radius (silhouette pixels
// depend on tessellation, not on lighting), or -1.
inline int sphereAtPixel(const SphereRows& rows, uint32_t x, uint32_t y) {
    const TestScene& s = rows.scene;
    glm::mat4 inverse = glm::inverse(s.camera.projection * s.camera.view);
    glm::vec2 ndc((float(x) + 0.5f) / float(s.width) * 2.0f - 1.0f,
                  (float(y) + 0.5f) / float(s.height) * 2.0f - 1.0f);
    glm::vec4 far = inverse * glm::vec4(ndc, 0.5f, 1.0f);
    glm::vec3 origin = s.camera.position;
    glm::vec3 dir = glm::normalize(glm::vec3(far) / far.w - origin);
    for (size_t i = 0; i < rows.centres.size(); ++i) {
        glm::vec3 oc = origin - rows.centres[i];
        float b = glm::dot(oc, dir);
        float r = SphereRows::kRadius * 0.95f;
        if (b * b - (glm::dot(oc, oc) - r * r) > 0.0f) return int(i);
    }
    return -1;
}

}  // namespace candela::render::test
