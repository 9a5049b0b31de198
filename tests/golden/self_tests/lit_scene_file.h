#pragma once
// The LitScene as an engine scene file: the camera and light as entities with components, the
// sphere and floor as mesh references into the LitScene glTF, the sphere's material as a
// scene-file override, so perturbations travel through the scene-file path.
#include <filesystem>
#include <string>

#include "lit_scene_gltf.h"

namespace candela::golden::test {

// Writes <dir>/<name>.gltf (meshes) and <dir>/<name>.scene.json; returns the scene file's
// path, or an empty path with `error` set.
std::filesystem::path writeLitSceneFile(const LitScene& scene, const std::filesystem::path& dir,
                                        const std::string& name, std::string& error);

}  // namespace candela::golden::test
