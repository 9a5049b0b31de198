// Bindings of the image-based lighting precompute shaders, shared by them and
// environment_precompute.cpp / environment_brdf_lut.cpp (valid in C++ and GLSL).
#ifndef CANDELA_IBL_BINDINGS_H
#define CANDELA_IBL_BINDINGS_H

// latlong_to_cube, cube_resample, cube_downsample, prefilter_ggx, irradiance_sh: the sampled
// source, and the written cube (storage image) or SH coefficients (storage buffer).
#define IBL_BINDING_SOURCE 0
#define IBL_BINDING_DESTINATION 1

// environment_brdf_lut.comp.
#define BRDF_LUT_BINDING_TEXELS 0

#endif
