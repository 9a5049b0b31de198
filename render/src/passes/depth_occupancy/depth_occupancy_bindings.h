// Bindings of depth_range.comp and depth_occupancy.comp, shared by them and
// depth_occupancy_pass.cpp (valid in C++ and GLSL).
#ifndef CANDELA_DEPTH_OCCUPANCY_BINDINGS_H
#define CANDELA_DEPTH_OCCUPANCY_BINDINGS_H

// depth_range.comp.
#define DEPTH_RANGE_BINDING_DEPTH 0
#define DEPTH_RANGE_BINDING_RANGE 1

// depth_occupancy.comp.
#define OCCUPANCY_BINDING_DEPTH 0
#define OCCUPANCY_BINDING_TILE_MASKS 1
#define OCCUPANCY_BINDING_CLUSTER_BOUNDS 2
#define OCCUPANCY_BINDING_DEPTH_RANGE 3

#endif
