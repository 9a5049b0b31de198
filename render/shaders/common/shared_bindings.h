// Binding numbers that the shared GLSL includes declare, for every pass that includes them
// (valid in C++ and GLSL): the passes' own bindings (<pass>_bindings.h) start after these.
#ifndef CANDELA_SHARED_BINDINGS_H
#define CANDELA_SHARED_BINDINGS_H

// camera.glsl: gbuffer.vert, the vertex stage of every mesh pass, reads it too.
#define CAMERA_BINDING 0
// light_buffer.glsl.
#define LIGHT_BUFFER_BINDING 1
// gbuffer.vert: each draw's previous-frame world matrix (motion vectors), indexed by
// gl_InstanceIndex (the draw's index in FrameScene::draws, passed as firstInstance). Above every
// pass's own numbers so the vertex stage can join any mesh pipeline.
#define PREVIOUS_WORLDS_BINDING 30

#endif
