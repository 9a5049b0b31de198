// Bindings of gbaa.comp, shared by the shader and gbaa_pass.cpp (valid in C++ and GLSL).
#ifndef CANDELA_GBAA_BINDINGS_H
#define CANDELA_GBAA_BINDINGS_H

#define GBAA_BINDING_HDR 0       // the lit HDR radiance (storage, read)
#define GBAA_BINDING_EDGES 1     // gbuffer.edges (sampled, texelFetch)
#define GBAA_BINDING_RESOLVED 2  // the antialiased radiance (storage, write)

#endif
