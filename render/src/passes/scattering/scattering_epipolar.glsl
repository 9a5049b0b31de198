// Epipolar geometry on the screen (Yusov 2014, GPU Pro 5, "High Performance Outdoor Light
// Scattering Using Epipolar Sampling" step 1; Yusov 2013 section 3): slice k's line runs from the
// sun's projection to the exit point k on the screen border, the exit points spaced evenly around
// it (in pixels, counter-clockwise from the bottom-left corner). The line enters the screen where
// the ray from the sun first meets it (at the sun when it is on the screen); a line whose exit
// point faces the sun crosses no pixel and is invalid. A pixel belongs between the two slices
// around the exit point of the ray from the sun through it.
#ifndef CANDELA_SCATTERING_EPIPOLAR_GLSL
#define CANDELA_SCATTERING_EPIPOLAR_GLSL

float screenPerimeter(vec2 size) { return 2.0 * (size.x + size.y); }

// The border point at perimeter position p (0..perimeter).
vec2 borderPoint(float p, vec2 size) {
    if (p < size.x) return vec2(p, 0.0);
    p -= size.x;
    if (p < size.y) return vec2(size.x, p);
    p -= size.y;
    if (p < size.x) return vec2(size.x - p, size.y);
    p -= size.x;
    return vec2(0.0, size.y - min(p, size.y));
}

// The perimeter position of a point on the border (the edge it is nearest).
float perimeterPosition(vec2 q, vec2 size) {
    q = clamp(q, vec2(0.0), size);
    vec4 distances = vec4(q.y, size.x - q.x, size.y - q.y, q.x);  // bottom, right, top, left
    float nearest = min(min(distances.x, distances.y), min(distances.z, distances.w));
    if (distances.x == nearest) return q.x;
    if (distances.y == nearest) return size.x + q.y;
    if (distances.z == nearest) return size.x + size.y + (size.x - q.x);
    return 2.0 * size.x + size.y + (size.y - q.y);
}

// Where the ray from `from` along `d` is inside the screen: (near, far) parameters (slab test).
vec2 screenSlab(vec2 from, vec2 d, vec2 size) {
    vec2 inv = 1.0 / mix(d, vec2(1e-12), lessThan(abs(d), vec2(1e-12)));
    vec2 t0 = (vec2(0.0) - from) * inv;
    vec2 t1 = (size - from) * inv;
    vec2 lo = min(t0, t1), hi = max(t0, t1);
    return vec2(max(lo.x, lo.y), min(hi.x, hi.y));
}

// Slice k's exit point, entry point, and whether its line crosses the screen.
bool sliceLine(uint k, uint slices, vec2 sun, vec2 size, out vec2 entry, out vec2 exitPoint) {
    exitPoint = borderPoint((float(k) + 0.5) / float(slices) * screenPerimeter(size), size);
    vec2 d = exitPoint - sun;
    vec2 slab = screenSlab(sun, d, size);
    float near = max(slab.x, 0.0);
    entry = sun + d * near;
    // The exit point must be where the ray leaves the screen, a pixel or more past the entry.
    return slab.y >= 1.0 - 1e-4 && length(exitPoint - entry) >= 1.0;
}

// The fractional slice of the pixel at `position` (slice k at k; wraps around at `slices`).
float pixelSlice(vec2 position, uint slices, vec2 sun, vec2 size) {
    vec2 d = position - sun;
    if (dot(d, d) < 1e-8) d = vec2(1.0, 0.0);
    vec2 slab = screenSlab(sun, d, size);
    vec2 exitPoint = clamp(sun + d * slab.y, vec2(0.0), size);
    return perimeterPosition(exitPoint, size) / screenPerimeter(size) * float(slices) - 0.5;
}

#endif
