#pragma once
// A hall whose far side is a colonnade, with the sun low behind it (issue 16's light-shaft
// scene): a floor, nine columns 8 m tall with gaps of 2 m, 10 m in front of the camera, a beam
// across their tops, a roof over the hall and a wall on its sunward side. The sun stands 14
// degrees up behind the columns, a little to the right, so its light comes into the hall
// through the gaps as shafts toward the camera. Shared by the light-shaft tests and report
// rows.
#include <glm/gtc/matrix_transform.hpp>

#include "test_scene.h"

namespace candela::render::test {

inline TestScene colonnadeScene(uint32_t width, uint32_t height) {
    TestScene scene;
    scene.width = width;
    scene.height = height;
    content::Material stone = lambertWhite();
    stone.baseColorFactor = {0.6f, 0.55f, 0.5f, 1.0f};
    scene.add(content::makePlane(40.0f, 1), stone);
    for (int i = -4; i <= 4; ++i) {
        scene.add(content::makeBox({0.5f, 4.0f, 0.5f}), stone,
                  glm::translate(glm::mat4(1.0f), glm::vec3(3.0f * float(i), 4.0f, -10.0f)));
    }
    scene.add(content::makeBox({13.0f, 0.5f, 0.8f}), stone,
              glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 8.5f, -10.0f)));
    scene.add(content::makeBox({13.5f, 0.3f, 10.8f}), stone,
              glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 9.3f, 0.0f)));
    scene.add(content::makeBox({0.3f, 4.8f, 10.8f}), stone,
              glm::translate(glm::mat4(1.0f), glm::vec3(13.5f, 4.8f, 0.0f)));
    LightInstance sun;
    sun.light.type = content::LightType::Directional;
    sun.light.lux = 100000.0f;
    sun.light.castShadows = true;
    const float elevation = glm::radians(14.0f);
    const glm::vec3 towardSun = glm::normalize(glm::vec3(0.25f, std::tan(elevation), -1.0f));
    sun.direction = -towardSun;
    scene.lights.push_back(sun);
    scene.lookAt(glm::vec3(-1.0f, 1.7f, 8.0f), glm::vec3(0.0f, 3.5f, -10.0f),
                 glm::vec3(0.0f, 1.0f, 0.0f));
    return scene;
}

}  // namespace candela::render::test
