#pragma once
// Interleaved vertex layout of uploaded meshes (the G-buffer pass's vertex input).
namespace candela::render {

struct MeshVertex {
    float position[3];
    float normal[3];
    float tangent[4];  // xyz, w = bitangent sign; zero when the mesh has none
    float uv0[2];
    float uv1[2];
    float color[4];  // linear RGBA; white when absent
};

}  // namespace candela::render
