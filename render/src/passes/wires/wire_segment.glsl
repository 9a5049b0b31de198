// One wire segment as wire_pass.cpp writes it (WireSegment) and the push block both wire
// shaders read.
#ifndef CANDELA_WIRE_SEGMENT_GLSL
#define CANDELA_WIRE_SEGMENT_GLSL

struct WireSegment {
    vec4 start;      // xyz world, w: the wire's radius (metres)
    vec4 end;        // xyz world, w: 1 unlit (emissive only), 0 lit
    vec4 baseColor;  // rgb linear, a: metallic
    vec4 emissive;   // rgb cd/m^2, a: roughness
};

layout(std430, binding = WIRE_BINDING_SEGMENTS) readonly buffer Segments {
    WireSegment segments[];
};

layout(push_constant) uniform WireDraw {
    ClusterGridParams grid;
    vec2 targetSize;            // pixels
    float pixelRadiusPerDepth;  // metres of half a pixel per metre of view depth
    float nearPlane;
    uint mode;                  // WIRE_MODE_*
    uint directionalCount;
    float skyIntensity;
    float prefilteredMipCount;
} draw;

#endif
