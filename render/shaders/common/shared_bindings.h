// Binding numbers that the shared GLSL includes declare, for every pass that includes them
// (valid in C++ and GLSL): the passes' own bindings (<pass>_bindings.h) start after these.
#ifndef CANDELA_SHARED_BINDINGS_H
#define CANDELA_SHARED_BINDINGS_H

// camera.glsl: gbuffer.vert, the vertex stage of every mesh pass, reads it too.
#define CAMERA_BINDING 0
// light_buffer.glsl.
#define LIGHT_BUFFER_BINDING 1

#endif
