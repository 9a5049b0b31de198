// The body both counting shaders share: the includer declares `imageSizeOf()` and `fetch()`
// for its kind of image binding. A texel adds to the slot's count when a channel the push
// constant asks about is NaN or Inf; an ordinary frame makes no atomic at all.
#ifndef CANDELA_NONFINITE_COUNT_GLSL
#define CANDELA_NONFINITE_COUNT_GLSL

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = NONFINITE_BINDING_COUNTS, std430) buffer Count {
    uint count;
};

layout(push_constant) uniform Push {
    uint channels;  // 3: rgb (radiance; alpha holds other things), 4: every channel
} push;

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, imageSizeOf()))) return;
    vec4 value = fetch(texel);
    if (push.channels < 4u) value.a = 0.0;
    if (any(isnan(value)) || any(isinf(value))) atomicAdd(count, 1u);
}

#endif
