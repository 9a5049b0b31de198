// One strand segment as hair_pass.cpp writes it (HairSegment), the A-buffer's node and the push
// block all hair shaders read.
#ifndef CANDELA_HAIR_SEGMENT_GLSL
#define CANDELA_HAIR_SEGMENT_GLSL

struct HairSegment {
    vec4 start;       // xyz world (root side), w: the strand's radius there (metres)
    vec4 end;         // xyz world (tip side), w: the radius there
    vec4 color;       // rgb linear K_d
    vec4 highlights;  // primary shift, secondary shift, primary exponent, secondary exponent
};

layout(std430, binding = HAIR_BINDING_SEGMENTS) readonly buffer Segments {
    HairSegment segments[];
};
// The segments past the first range's reach (the same buffer further on; unused otherwise).
layout(std430, binding = HAIR_BINDING_SEGMENTS_HIGH) readonly buffer SegmentsHigh {
    HairSegment segmentsHigh[];
};

// Segment i of the frame: the first range holds as many as its binding reaches (its length).
// Copied member by member: a buffer's struct and a local one are different SPIR-V types, which
// this glslang would store one into the other (invalid SPIR-V).
HairSegment hairSegment(uint i) {
    const uint low = uint(segments.length());
    HairSegment s;
    if (i < low) {
        s.start = segments[i].start;
        s.end = segments[i].end;
        s.color = segments[i].color;
        s.highlights = segments[i].highlights;
    } else {
        const uint j = i - low;
        s.start = segmentsHigh[j].start;
        s.end = segmentsHigh[j].end;
        s.color = segmentsHigh[j].color;
        s.highlights = segmentsHigh[j].highlights;
    }
    return s;
}

#ifndef HAIR_NO_LISTS
// A node of a pixel's list: x the fragment's depth (float bits, reverse-Z), y its segment, z
// its coverage (float bits), w the next node (HAIR_LIST_END: none).
layout(std430, binding = HAIR_BINDING_NODES) buffer Nodes {
    uvec4 nodes[];
};
layout(std430, binding = HAIR_BINDING_HEADS) buffer Heads {
    uint heads[];
};
#endif

layout(push_constant) uniform HairDraw {
    ClusterGridParams grid;
    vec2 targetSize;            // pixels
    float pixelRadiusPerDepth;  // metres of half a pixel per metre of view depth
    float nearPlane;
    uint mode;                  // HAIR_MODE_*
    uint directionalCount;
    float skyIntensity;
    uint nodeCapacity;          // nodes in the pool
    uint selfShadow;            // HAIR_SELF_SHADOW_*
    uint shadowView;            // hair_shadow.vert: the shadow view drawn
    uint segmentCount;          // segments in the frame (the self-shadow reference's loop)
    uint pad;
} draw;

#ifndef HAIR_NO_LISTS
uint pixelIndex(vec2 fragCoord) {
    return uint(fragCoord.y) * uint(draw.targetSize.x) + uint(fragCoord.x);
}
#endif

#endif
