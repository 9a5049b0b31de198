// The lights a lit pass adds at one pixel, in the order every pass adds them: the directional
// lights, then the pixel's cluster list; every light for the brute-force reference and for a
// cluster whose list did not fit the device-assigned index buffer (light_assignment_pass.h), so
// no light is ever dropped. Walk them with one loop and one call of the pass's light function:
//
//     PixelLights lights = pixelLights(kClustered, directionalCount, grid, pixel, depth);
//     for (uint k = 0u; k < pixelLightCount(lights); ++k) {
//         uint light = pixelLightAt(lights, k);
//         if (light != kNoLight) radiance += lightRadiance(..., light);
//     }
//
// Why one call site: compilers inline the light function (all of light evaluation, shadows and
// shading) once per call. The four loops each pass had made lavapipe compile the lighting pass
// in 17 s instead of 5.
// Include after clusters.glsl, lights.glsl and the declarations of camera, lightIndices[],
// clusterRanges[] and depthRange[].
#ifndef CANDELA_PIXEL_LIGHTS_GLSL
#define CANDELA_PIXEL_LIGHTS_GLSL

// A cluster's count when its list overflowed.
const uint kListOverflow = 0xffffffffu;

struct PixelLights {
    uint directionalCount;  // listed first, from lightIndices[0..)
    uint listFirst;
    uint listCount;   // the cluster's entries, or every light
    uint quarterBit;  // the pixel's quarter of its tile, for the entries' masks
    bool everyLight;  // brute force, or an overflowing cluster
    bool clustered;
};

PixelLights pixelLights(bool clustered, uint directionalCount, ClusterGridParams grid, uvec2 pixel,
                        float ndcDepth) {
    PixelLights lights;
    lights.directionalCount = 0u;
    lights.listFirst = 0u;
    lights.listCount = camera.frameInfo.z;
    lights.quarterBit = 0u;
    lights.everyLight = true;
    lights.clustered = clustered;
    if (clustered) {
        lights.directionalCount = directionalCount;
        // The slicing the depth occupancy pass derived ([2] sliceNear, [3] logRatio).
        uint cluster = clusterOfPixel(grid, pixel, ndcDepth, uintBitsToFloat(depthRange[2]),
                                      uintBitsToFloat(depthRange[3]));
        uint count = clusterRanges[2u * cluster + 1u];
        lights.everyLight = count == kListOverflow;
        if (!lights.everyLight) {
            lights.listFirst = clusterRanges[2u * cluster];
            lights.listCount = count;
            lights.quarterBit = quarterBitOfPixel(grid, pixel);
        }
    }
    return lights;
}

// The brute-force lights [first, end) of `lights` (pixelLights(false, ...)): a dispatch that
// takes every light a batch at a time.
PixelLights pixelLightRange(PixelLights lights, uint first, uint end) {
    lights.listFirst = first;
    lights.listCount = min(end, lights.listCount) - min(first, lights.listCount);
    return lights;
}

uint pixelLightCount(PixelLights lights) {
    return lights.directionalCount + lights.listCount;
}

// The k-th light's index, or kNoLight for an entry that does not reach the pixel's quarter.
uint pixelLightAt(PixelLights lights, uint k) {
    if (k < lights.directionalCount) return lightIndices[k];
    uint i = k - lights.directionalCount;
    if (!lights.everyLight) return lightOfEntry(lightIndices[lights.listFirst + i], lights.quarterBit);
    // An overflowing cluster: the directional lights came first. Stream 3's w is the light type
    // (light_buffer.glsl).
    if (lights.clustered && lightInEveryCluster(uint(lightData[3u * camera.frameInfo.w + i].w))) {
        return kNoLight;
    }
    return lights.listFirst + i;  // 0 but for a range of the brute-force lights
}

// The k-th entry's light index whatever its quarter bits (kNoLight as pixelLightAt for an
// overflowing cluster's directional lights): what a walk by light class tests.
uint pixelLightIndexAt(PixelLights lights, uint k) {
    if (k < lights.directionalCount || lights.everyLight) return pixelLightAt(lights, k);
    return lightIndices[lights.listFirst + k - lights.directionalCount] & LIGHT_ENTRY_INDEX_MASK;
}

#endif
