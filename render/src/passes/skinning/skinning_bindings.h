// Bindings, push constants and buffer layouts of skinning.comp, shared by the shader,
// skinning_pass.cpp and scene_resources.cpp (valid in C++ and GLSL).
#ifndef CANDELA_SKINNING_BINDINGS_H
#define CANDELA_SKINNING_BINDINGS_H

#define SKINNING_BINDING_SOURCE 0         // the mesh's bind-pose MeshVertex array (floats)
#define SKINNING_BINDING_SKIN 1           // per vertex: uvec4 joints, vec4 weights
#define SKINNING_BINDING_MORPH_DELTAS 2   // vec4 per (target, attribute, vertex), see below
#define SKINNING_BINDING_JOINTS 3         // mat4 joint matrices of every instance this frame
#define SKINNING_BINDING_MORPH_WEIGHTS 4  // float morph weights of every instance this frame
#define SKINNING_BINDING_TARGET 5         // the instance's deformed MeshVertex array (floats)

// MeshVertex (mesh_vertex.h) as floats: position 0..2, normal 3..5, tangent 6..9, then uvs
// and colour, which the pass copies unchanged.
#define SKINNING_VERTEX_FLOATS 18
#define SKINNING_NORMAL_OFFSET 3
#define SKINNING_TANGENT_OFFSET 6

// Morph deltas of target t, attribute a (0 position, 1 normal, 2 tangent), vertex v at
// (t * 3 + a) * vertexCount + v; zero where the file gives none.
#define SKINNING_MORPH_ATTRIBUTES 3

#define SKINNING_GROUP_SIZE 64

#endif
