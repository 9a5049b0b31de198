// Shadow constants shared by the C++ that plans and packs shadow views (shadow_pass.cpp,
// shadow_views.h) and the GLSL that samples them (common/shadows.glsl), valid in both
// languages. The shadow depth pass itself binds no descriptors (push constants only); the
// passes that sample shadows give their own binding numbers (LIGHTING_BINDING_SHADOW_*,
// FORWARD_BINDING_SHADOW_*) and name them for common/shadows.glsl.
#ifndef CANDELA_SHADOWS_BINDINGS_H
#define CANDELA_SHADOWS_BINDINGS_H

// GpuShadowView::params.y: how the view projects.
#define SHADOW_KIND_ORTHOGRAPHIC 0u  // directional cascades: linear depth, reversed
#define SHADOW_KIND_PERSPECTIVE 1u   // spot and cube faces: reverse-Z, infinite far
// A light without a shadow map (its entry in the per-light table).
#define SHADOW_NO_VIEW 0xffffffffu
// Cube faces of a point light's shadow, in major-axis order +X, -X, +Y, -Y, +Z, -Z.
#define SHADOW_CUBE_FACES 6u
#define SHADOW_MAX_CASCADES 4u
// Spot lights up to this outer half-angle (radians, about 74.5 degrees) get one perspective
// view; wider cones, whose single view would stretch its texels toward the rim (and cannot
// reach 90 degrees), get the six cube faces of a point light.
#define SHADOW_MAX_SPOT_HALF_ANGLE 1.3

#endif
