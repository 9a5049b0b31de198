// Bindings and histogram layout of luminance_histogram.comp, shared by the shader,
// exposure_pass.cpp and auto_exposure.cpp (valid in C++ and GLSL).
#ifndef CANDELA_EXPOSURE_BINDINGS_H
#define CANDELA_EXPOSURE_BINDINGS_H

#define EXPOSURE_BINDING_HDR 0        // storage image, read
#define EXPOSURE_BINDING_HISTOGRAM 1  // storage buffer: HISTOGRAM_BINS uints

// Bins of a quarter EV100 each from HISTOGRAM_MIN_EV100 (luminance 1.2 * 2^EV / ... see
// auto_exposure.h); pixels darker than the first bin's edge (black included) are not counted.
#define HISTOGRAM_BINS 128
#define HISTOGRAM_MIN_EV100 (-8.0)
#define HISTOGRAM_BINS_PER_EV 4.0

#endif
