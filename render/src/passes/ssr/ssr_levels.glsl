// Where each Hi-Z level lies in the pyramid image (ssr_pass.h pyramidDesc): level 0 at the
// origin with the frame's size; level k > 0 at (width, sum of the heights of levels 1..k-1),
// each ceil(half) of the one before.
#ifndef CANDELA_SSR_LEVELS_GLSL
#define CANDELA_SSR_LEVELS_GLSL

#include "common/camera.glsl"

struct SsrLevel {
    ivec2 origin;
    ivec2 size;
};

SsrLevel ssrLevel(uint level) {
    ivec2 size = ivec2(camera.frameInfo.xy);
    SsrLevel l = SsrLevel(ivec2(0), size);
    for (uint k = 1u; k <= level; ++k) {
        l.origin = ivec2(int(camera.frameInfo.x), k == 1u ? 0 : l.origin.y + l.size.y);
        l.size = (l.size + 1) / 2;
    }
    return l;
}

#endif
