#pragma once
// Evaluating glTF animation samplers at a time: STEP, LINEAR (slerp for rotations) and
// CUBICSPLINE (Hermite, tangents scaled by the key interval, glTF 2.0 appendix C). Times
// outside the keys clamp to the first/last value. Allocation-free.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

#include "candela/content/animation.h"

namespace candela::content {

// Writes sampler.components floats into `out` (out.size() >= components). Rotations (x, y, z,
// w) come out unit length.
void sampleAnimation(const AnimationSampler& sampler, AnimatedProperty property, float time,
                     std::span<float> out);
// The same, starting the key search at `cursor` (the interval found last time, updated):
// playback moves forward a key or less per frame, so the search is O(1) amortised instead of
// a binary search per channel. Any cursor value gives the same result.
void sampleAnimation(const AnimationSampler& sampler, AnimatedProperty property, float time,
                     std::span<float> out, std::uint32_t& cursor);

// The same, but a rotation comes out as interpolated, not yet unit length: callers that
// sample many channels normalise them together afterwards with normalizeQuaternions (the
// same values as sampleAnimation's).
void sampleAnimationUnnormalised(const AnimationSampler& sampler, AnimatedProperty property,
                                 float time, std::span<float> out, std::uint32_t& cursor);
// Scales each quaternion (x, y, z, w; 4 floats at each pointer) to unit length, or makes it
// the identity when its length is below 1e-20: four at a time with SSE2, the same values as
// one at a time.
void normalizeQuaternions(std::span<float* const> quaternions);

// A LINEAR translation or scale (rotation false), or a LINEAR rotation whose key interval k
// holds a corrected nlerp, at parameter t in [times[k], times[k+1]] (t = (time - times[k]) /
// (times[k+1] - times[k]), k + 1 < keys): writes the same values as
// sampleAnimationUnnormalised and returns true; false (nothing written) otherwise.
inline bool sampleLinearAt(const AnimationSampler& sampler, bool rotation, std::size_t k, float t,
                           float* out) {
    const std::size_t n = rotation ? 4 : 3;
    if (sampler.interpolation != Interpolation::Linear || sampler.components != n) return false;
    const float* a = sampler.values.data() + k * n;
    const float* b = a + n;
    if (!rotation) {
        for (std::size_t c = 0; c < 3; ++c)
            out[c] = a[c] + (b[c] - a[c]) * t;
        return true;
    }
    const std::size_t keys = sampler.times.size();
    if (sampler.slerpAngles.size() != kSlerpAngleFloats * (keys - 1)) return false;
    const float* entry = sampler.slerpAngles.data() + kSlerpAngleFloats * k;
    if (entry[3] == 0) return false;  // an exact-slerp interval
    // The corrected nlerp's weights and sum, as the general path computes them.
    const float w = t * (1 - t);
    const float u = t + w * (2 * t - 1) * (entry[0] + entry[1] * w);
    const float wa = 1 - u, wb = entry[2] * u;
#if defined(__SSE2__)
    // One 16-byte store, per lane the same product and sum: normalizeQuaternions reloads the
    // quaternion as one vector a few channels later, which four scalar stores would stall
    // (a wide load cannot be forwarded from narrower stores still in flight).
    _mm_storeu_ps(out, _mm_add_ps(_mm_mul_ps(_mm_set1_ps(wa), _mm_loadu_ps(a)),
                                  _mm_mul_ps(_mm_set1_ps(wb), _mm_loadu_ps(b))));
#else
    for (std::size_t c = 0; c < 4; ++c)
        out[c] = wa * a[c] + wb * b[c];
#endif
    return true;
}

// The hot case of sampleAnimation, inline: a LINEAR translation or scale (3 components), or a
// LINEAR rotation whose interval holds a corrected nlerp (see prepareSlerpAngles), at a time
// in the cursor's key interval or the next one (forward playback). Writes the same values as
// sampleAnimationUnnormalised and returns true; returns false (nothing written, cursor kept)
// in every other case, for the caller to take the general path.
inline bool sampleLinearInCursorInterval(const AnimationSampler& sampler, bool rotation, float time,
                                         float* out, std::uint32_t& cursor) {
    const std::size_t n = rotation ? 4 : 3;
    const std::size_t keys = sampler.times.size();
    if (sampler.interpolation != Interpolation::Linear || sampler.components != n) return false;
    const float* times = sampler.times.data();
    std::size_t k = cursor;
    if (!(k + 1 < keys && times[k] <= time && time < times[k + 1] && time > times[0])) {
        if (!(k + 2 < keys && times[k + 1] <= time && time < times[k + 2] && time > times[0]))
            return false;
        ++k;
    }
    const float t0 = times[k];
    const float t = (time - t0) / (times[k + 1] - t0);
    if (!sampleLinearAt(sampler, rotation, k, t, out)) return false;
    cursor = static_cast<std::uint32_t>(k);
    return true;
}

// Every rotation of clip.sharedRotations (a linearSharedTimes clip) at key interval k and
// parameter t, four tracks at a time: the same unit quaternions sampleLinearAt followed by
// normalizeQuaternions gives (per lane the same products, sums, square root and divisions),
// each written through rotationAt(channel index), a float* to 4 floats (x, y, z, w).
template <class RotationAt>
void sampleSharedRotations(const SharedKeyRotations& plan, std::size_t k, float t,
                           RotationAt&& rotationAt) {
    constexpr std::size_t lanes = SharedKeyRotations::kLanes;
    const std::size_t groups = plan.groups();
    const std::size_t count = plan.rotationChannels.size();
    const float w = t * (1 - t);
    const float skew = 2 * t - 1;
    for (std::size_t g = 0; g < groups; ++g) {
        const float* a = plan.keys.data() + (k * groups + g) * 4 * lanes;
        const float* b = a + groups * 4 * lanes;
        const float* correction = plan.corrections.data() + (k * groups + g) * 3 * lanes;
        const std::size_t first = g * lanes;
        const std::size_t used = count - first < lanes ? count - first : lanes;
#if defined(__SSE2__)
        // sampleLinearAt's u = t + w (2t - 1)(k1 + k2 w), wa = 1 - u, wb = sign u, per lane.
        const __m128 k1 = _mm_loadu_ps(correction), k2 = _mm_loadu_ps(correction + lanes);
        const __m128 sign = _mm_loadu_ps(correction + 2 * lanes);
        const __m128 vw = _mm_set1_ps(w);
        const __m128 u = _mm_add_ps(_mm_set1_ps(t), _mm_mul_ps(_mm_mul_ps(vw, _mm_set1_ps(skew)),
                                                               _mm_add_ps(k1, _mm_mul_ps(k2, vw))));
        const __m128 wa = _mm_sub_ps(_mm_set1_ps(1.0f), u), wb = _mm_mul_ps(sign, u);
        auto blend = [&](std::size_t c) {
            return _mm_add_ps(_mm_mul_ps(wa, _mm_loadu_ps(a + c * lanes)),
                              _mm_mul_ps(wb, _mm_loadu_ps(b + c * lanes)));
        };
        __m128 x = blend(0), y = blend(1), z = blend(2), qw = blend(3);
        // normalizeQuaternions' arithmetic, already in structure of arrays.
        const __m128 sum =
            _mm_add_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(x, x), _mm_mul_ps(y, y)), _mm_mul_ps(z, z)),
                       _mm_mul_ps(qw, qw));
        const __m128 length = _mm_sqrt_ps(sum);
        const __m128 usable = _mm_cmpgt_ps(length, _mm_set1_ps(1e-20f));
        auto pick = [&](__m128 normalised, __m128 fallback) {
            return _mm_or_ps(_mm_and_ps(usable, normalised), _mm_andnot_ps(usable, fallback));
        };
        x = pick(_mm_div_ps(x, length), _mm_setzero_ps());
        y = pick(_mm_div_ps(y, length), _mm_setzero_ps());
        z = pick(_mm_div_ps(z, length), _mm_setzero_ps());
        qw = pick(_mm_div_ps(qw, length), _mm_set1_ps(1.0f));
        _MM_TRANSPOSE4_PS(x, y, z, qw);
        const __m128 quaternions[lanes] = {x, y, z, qw};
        for (std::size_t lane = 0; lane < used; ++lane)
            _mm_storeu_ps(rotationAt(plan.rotationChannels[first + lane]), quaternions[lane]);
#else
        for (std::size_t lane = 0; lane < used; ++lane) {
            const float u = t + w * skew * (correction[lane] + correction[lanes + lane] * w);
            const float wa = 1 - u, wb = correction[2 * lanes + lane] * u;
            float q[4];
            for (std::size_t c = 0; c < 4; ++c)
                q[c] = wa * a[c * lanes + lane] + wb * b[c * lanes + lane];
            float* out = rotationAt(plan.rotationChannels[first + lane]);
            std::copy_n(q, 4, out);
            float* const one[1] = {out};
            normalizeQuaternions(one);
        }
#endif
    }
}

// Index k of the key interval [times[k], times[k+1]] holding `time` (0 before the first key,
// times.size() - 1 from the last key on).
std::size_t keyIntervalAt(const std::vector<float>& times, float time);
// The same, trying `cursor` and the interval after it before searching; updates `cursor`.
std::size_t keyIntervalAt(const std::vector<float>& times, float time, std::uint32_t& cursor);

// Fills sampler.slerpAngles for a LINEAR rotation sampler (clears them for any other): per
// key interval either a corrected normalised lerp, where its error against slerp, measured
// here, is at most `nlerpTolerance` radians (no sine per frame; sampler.rotationErrorBound
// keeps the largest), or slerp's angle and sine (which slerp would otherwise compute with an
// acos and a sine per channel per frame, same values). The loader calls it with
// kNlerpErrorTolerance; 0 is the reference mode: exact slerp everywhere.
void prepareSlerpAngles(AnimationSampler& sampler, double nlerpTolerance = kNlerpErrorTolerance);

// Sets clip.linearSharedTimes: every sampler LINEAR, with two keys or more, and all with
// bit-for-bit the same key times. The loader calls it.
void markSharedKeyTimes(AnimationClip& clip);

// Wraps or clamps a play time into [0, duration].
float clipTime(float time, float duration, bool loop);

}  // namespace candela::content
