// Bindings of the light assignment shaders (assign_lights.comp, allocate_lists.comp,
// sort_lists.comp), shared by them and light_assignment_pass.cpp (valid in C++ and GLSL).
#ifndef CANDELA_LIGHT_ASSIGNMENT_BINDINGS_H
#define CANDELA_LIGHT_ASSIGNMENT_BINDINGS_H

#include "common/shared_bindings.h"

// assign_lights.comp (count and write walks); the lights at LIGHT_BUFFER_BINDING.
#define ASSIGN_BINDING_OCCUPANCY 2
#define ASSIGN_BINDING_CLUSTER_BOUNDS 3
#define ASSIGN_BINDING_DEPTH_RANGE 4
#define ASSIGN_BINDING_CLUSTER_COUNTS 5
#define ASSIGN_BINDING_CLUSTER_RANGES 6
#define ASSIGN_BINDING_LIGHT_INDICES 7

// allocate_lists.comp.
#define ALLOCATE_BINDING_CLUSTER_COUNTS 0
#define ALLOCATE_BINDING_CLUSTER_RANGES 1
#define ALLOCATE_BINDING_LIST_USAGE 2
#define ALLOCATE_BINDING_OCCUPANCY 3
#define ALLOCATE_BINDING_PREVIOUS_OCCUPANCY 4

// sort_lists.comp.
#define SORT_BINDING_CLUSTER_RANGES 0
#define SORT_BINDING_LIGHT_INDICES 1
#define SORT_BINDING_CLUSTER_COUNTS 2
#define SORT_BINDING_OCCUPANCY 3

#endif
