// GBAA's edge target (gbuffer.edges, written by the G-buffer pass's edge variant under
// --aa gbaa; render/README.md "GBAA"), shared by common/gbaa_edges.glsl, the resolve
// (passes/gbaa/gbaa.comp) and C++ (valid in both).
#ifndef CANDELA_GBAA_EDGES_H
#define CANDELA_GBAA_EDGES_H

// What a channel holds where no edge of the pixel's triangle lies within 1.5 pixels of its
// centre on that side (also the target's clear value, where nothing is drawn).
#define GBAA_NO_EDGE 2.0

#endif
