// Exposure, tonemapping and output encoding, shared by the tonemap pass and its tests.
#ifndef CANDELA_COLOR_GLSL
#define CANDELA_COLOR_GLSL

// Photometric exposure from EV100 (saturation-based sensitivity, K = 12.5, q = 0.65):
// the luminance that maps to 1.0 is 1.2 * 2^EV100.
float exposureFromEv100(float ev100) {
    return 1.0 / (1.2 * exp2(ev100));
}

// ACES filmic curve fit (Narkowicz 2015) applied per channel: a cheap filmic shoulder.
vec3 tonemapAcesFit(vec3 x) {
    const float a = 2.51;
    const float b = 0.03;
    const float c = 2.43;
    const float d = 0.59;
    const float e = 0.14;
    return clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0, 1.0);
}

// IEC 61966-2-1 sRGB encoding of linear [0, 1] values.
vec3 linearToSrgb(vec3 linear) {
    vec3 low = linear * 12.92;
    vec3 high = 1.055 * pow(linear, vec3(1.0 / 2.4)) - 0.055;
    return mix(high, low, lessThanEqual(linear, vec3(0.0031308)));
}

#endif
