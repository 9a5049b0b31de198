// Screen-space motion: where this fragment was in the previous frame, as the texture-space
// offset current - previous (x right, y down, in units of the target size). TAA reads the
// history at uv - motion. Both clip positions are unjittered, so a static pixel gets exactly 0.
#ifndef CANDELA_MOTION_VECTORS_GLSL
#define CANDELA_MOTION_VECTORS_GLSL

vec2 screenMotion(vec4 currentClip, vec4 previousClip) {
    vec2 current = currentClip.xy / currentClip.w;
    vec2 previous = previousClip.xy / max(previousClip.w, 1e-6);
    return (current - previous) * 0.5;  // NDC spans 2, texture space 1
}

#endif
