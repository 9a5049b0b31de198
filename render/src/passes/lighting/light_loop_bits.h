// lighting.comp's local-light loops, one bit each in SPEC_LIGHT_LOOPS (valid in GLSL and C++;
// light_loops.h says which a frame needs).
#ifndef CANDELA_LIGHT_LOOP_BITS_H
#define CANDELA_LIGHT_LOOP_BITS_H

#define LIGHT_LOOP_PLAIN 1u                // no map; a point or spot without a size
#define LIGHT_LOOP_UNSHADOWED_PUNCTUAL 2u  // no map; not a rect or disk (sphere, tube)
#define LIGHT_LOOP_UNSHADOWED 4u           // no map (rect, disk)
#define LIGHT_LOOP_PUNCTUAL 8u             // not a rect or disk, a map or not
#define LIGHT_LOOP_ANY 16u                 // any light (brute force; a mapped rect or disk)
#define LIGHT_LOOPS_ALL 31u

#endif
