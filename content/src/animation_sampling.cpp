#include "candela/content/animation_sampling.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>
#if defined(__SSE2__)
#include <emmintrin.h>
#include <xmmintrin.h>
#endif

namespace candela::content {
namespace {

// q / |q|, or the identity for a zero quaternion. With SSE2 the squares are summed in the
// scalar order ((x² + y²) + z²) + w² and the four correctly rounded divisions are one divps:
// the same values as the scalar form, without four dependent scalar divisions per channel.
inline void normalizeQuaternion(float* q) {
#if defined(__SSE2__)
    const __m128 v = _mm_loadu_ps(q);
    const __m128 squares = _mm_mul_ps(v, v);
    __m128 sum = _mm_add_ss(squares, _mm_shuffle_ps(squares, squares, _MM_SHUFFLE(1, 1, 1, 1)));
    sum = _mm_add_ss(sum, _mm_shuffle_ps(squares, squares, _MM_SHUFFLE(2, 2, 2, 2)));
    sum = _mm_add_ss(sum, _mm_shuffle_ps(squares, squares, _MM_SHUFFLE(3, 3, 3, 3)));
    const __m128 length = _mm_sqrt_ss(sum);
    if (_mm_cvtss_f32(length) > 1e-20f) {
        _mm_storeu_ps(q, _mm_div_ps(v, _mm_shuffle_ps(length, length, _MM_SHUFFLE(0, 0, 0, 0))));
        return;
    }
#else
    const float length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (length > 1e-20f) {
        for (int c = 0; c < 4; ++c)
            q[c] /= length;
        return;
    }
#endif
    q[0] = q[1] = q[2] = 0;
    q[3] = 1;
}

// The arc between two keys: the cosine (made non-negative: the shorter arc), its sign, and
// when the keys are far enough apart for the trigonometric form, the angle and its sine.
struct Arc {
    float sign;
    bool trigonometric;
    float theta;
    float sinTheta;
};

Arc arcBetween(const float* a, const float* b) {
    float cosTheta = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
    const float sign = cosTheta < 0 ? -1.0f : 1.0f;
    cosTheta *= sign;
    if (!(cosTheta < 0.9995f)) return {sign, false, 0, 0};
    const float theta = std::acos(cosTheta);
    return {sign, true, theta, std::sin(theta)};
}

// Shortest-arc spherical interpolation, before the final normalisation (the caller's); falls
// back to lerp when nearly parallel.
// `cached`: the interval's entry from prepareSlerpAngles (the angle, sine and arc sign that
// arcBetween computes, so the same results, or a corrected nlerp's coefficients), or null.
void slerp(const float* a, const float* b, float t, float* out, const float* cached) {
    float sign, wa = 1 - t, wb = t;
    if (cached != nullptr) {
        sign = cached[2];
        if (cached[3] != 0) {
            // Corrected normalised lerp (see prepareSlerpAngles): u(t) = t + w (2t - 1)
            // (k1 + k2 w), w = t (1 - t), puts the normalised lerp within
            // kNlerpErrorTolerance of the slerp, with no sine or division per frame.
            const float w = t * (1 - t);
            const float u = t + w * (2 * t - 1) * (cached[0] + cached[1] * w);
            wa = 1 - u;
            wb = u;
        } else if (cached[1] != 0) {
            wa = std::sin((1 - t) * cached[0]) / cached[1];
            wb = std::sin(t * cached[0]) / cached[1];
        }
    } else {
        const Arc arc = arcBetween(a, b);
        sign = arc.sign;
        if (arc.trigonometric) {
            wa = std::sin((1 - t) * arc.theta) / arc.sinTheta;
            wb = std::sin(t * arc.theta) / arc.sinTheta;
        }
    }
#if defined(__SSE2__)
    // wa a + (sign wb) b on whole quaternions: the scalar form's products and sums.
    _mm_storeu_ps(out, _mm_add_ps(_mm_mul_ps(_mm_set1_ps(wa), _mm_loadu_ps(a)),
                                  _mm_mul_ps(_mm_set1_ps(sign * wb), _mm_loadu_ps(b))));
#else
    for (std::size_t c = 0; c < 4; ++c)
        out[c] = wa * a[c] + sign * wb * b[c];
#endif
}

}  // namespace

std::size_t keyIntervalAt(const std::vector<float>& times, float time) {
    if (times.size() < 2 || time <= times.front()) return 0;
    if (time >= times.back()) return times.size() - 1;
    // First key after `time`, minus one: times[k] <= time < times[k + 1].
    const auto next = std::upper_bound(times.begin(), times.end(), time);
    return static_cast<std::size_t>(next - times.begin()) - 1;
}

std::size_t keyIntervalAt(const std::vector<float>& times, float time, std::uint32_t& cursor) {
    const std::size_t n = times.size();
    std::size_t k = cursor;
    if (n >= 2 && k + 1 < n && times[k] <= time && time > times.front()) {
        if (time < times[k + 1]) return k;
        if (k + 2 < n && time < times[k + 2]) return cursor = static_cast<std::uint32_t>(k + 1);
    }
    k = keyIntervalAt(times, time);
    cursor = static_cast<std::uint32_t>(k);
    return k;
}

namespace {

// The nlerp parameter u whose normalised lerp points exactly where slerp(t) does
// (the slerp weights' ratio), and the arc angle a normalised lerp at u reaches.
double exactNlerpParameter(double t, double theta) {
    const double a = std::sin((1 - t) * theta), b = std::sin(t * theta);
    return b / (a + b);
}
double nlerpAngle(double u, double theta) {
    return std::atan2(u * std::sin(theta), (1 - u) + u * std::cos(theta));
}

struct NlerpFit {
    float k1, k2;
    double error;  // the largest arc angle to the slerp over the interval (radians)
};

// Least-squares fit of u(t) - t = w (2t - 1) (k1 + k2 w), w = t (1 - t) (the correction is
// odd about t = 1/2, as slerp is symmetric), then its error measured on a fine grid.
NlerpFit fitNlerp(double theta) {
    constexpr int kFitSamples = 32, kCheckSamples = 256;
    // (Nearly) equal keys: plain nlerp, off by about theta^3 / 60 at most (and u is 0/0).
    if (theta < 1e-4) return {0, 0, theta * theta * theta};
    double s11 = 0, s12 = 0, s22 = 0, r1 = 0, r2 = 0;
    for (int i = 1; i < kFitSamples; ++i) {
        const double t = static_cast<double>(i) / kFitSamples, w = t * (1 - t);
        const double b1 = w * (2 * t - 1), b2 = b1 * w;
        const double d = exactNlerpParameter(t, theta) - t;
        s11 += b1 * b1;
        s12 += b1 * b2;
        s22 += b2 * b2;
        r1 += b1 * d;
        r2 += b2 * d;
    }
    const double det = s11 * s22 - s12 * s12;
    NlerpFit fit{static_cast<float>((r1 * s22 - r2 * s12) / det),
                 static_cast<float>((s11 * r2 - s12 * r1) / det), 0};
    for (int i = 1; i < kCheckSamples; ++i) {
        const double t = static_cast<double>(i) / kCheckSamples, w = t * (1 - t);
        const double u = t + w * (2 * t - 1) * (fit.k1 + fit.k2 * w);
        fit.error = std::max(fit.error, std::fabs(nlerpAngle(u, theta) - t * theta));
    }
    return fit;
}

}  // namespace

void prepareSlerpAngles(AnimationSampler& sampler, double nlerpTolerance) {
    sampler.slerpAngles.clear();
    sampler.rotationErrorBound = 0;
    if (sampler.interpolation != Interpolation::Linear || sampler.components != 4 ||
        sampler.times.size() < 2 || sampler.values.size() != 4 * sampler.times.size())
        return;
    sampler.slerpAngles.resize(kSlerpAngleFloats * (sampler.times.size() - 1));
    for (std::size_t k = 0; k + 1 < sampler.times.size(); ++k) {
        const float* a = &sampler.values[4 * k];
        const float* b = &sampler.values[4 * (k + 1)];
        const Arc arc = arcBetween(a, b);
        float* interval = &sampler.slerpAngles[kSlerpAngleFloats * k];
        interval[2] = arc.sign;
        // The keys' own arc, in double (unit keys: the loader's values may be a little off).
        const double dot =
            std::fabs(static_cast<double>(a[0]) * b[0] + static_cast<double>(a[1]) * b[1] +
                      static_cast<double>(a[2]) * b[2] + static_cast<double>(a[3]) * b[3]);
        const double theta = std::acos(std::min(1.0, dot));
        const NlerpFit fit = fitNlerp(theta);
        if (nlerpTolerance > 0 && fit.error <= nlerpTolerance) {
            interval[0] = fit.k1;
            interval[1] = fit.k2;
            interval[3] = 1;  // corrected nlerp
            sampler.rotationErrorBound =
                std::max(sampler.rotationErrorBound, static_cast<float>(fit.error));
            continue;
        }
        // Too wide an arc for the correction: slerp, with its angle and sine. A zero sine
        // would mark plain lerp (a real one is never 0 here: theta is at least acos(0.9995)).
        interval[0] = arc.theta;
        interval[1] = arc.trigonometric ? arc.sinTheta : 0.0f;
        interval[3] = 0;
    }
}

namespace {

// Fills clip.sharedRotations where every channel is a translation, rotation or scale of its
// own node and property (glTF allows one channel per target), translations and scales have 3
// components, and every rotation interval holds a corrected nlerp; leaves it empty otherwise
// (the per-channel path then samples the clip).
void buildSharedKeyRotations(AnimationClip& clip) {
    SharedKeyRotations plan;
    std::vector<std::pair<std::int32_t, AnimatedProperty>> targets;
    for (std::size_t c = 0; c < clip.channels.size(); ++c) {
        const AnimationChannel& channel = clip.channels[c];
        if (channel.sampler < 0 ||
            static_cast<std::size_t>(channel.sampler) >= clip.samplers.size())
            return;
        const AnimationSampler& sampler = clip.samplers[static_cast<std::size_t>(channel.sampler)];
        const std::pair target{channel.node, channel.property};
        if (channel.node < 0 || std::find(targets.begin(), targets.end(), target) != targets.end())
            return;
        targets.push_back(target);
        switch (channel.property) {
            case AnimatedProperty::Rotation: {
                const std::size_t intervals = sampler.times.size() - 1;
                if (sampler.components != 4 ||
                    sampler.slerpAngles.size() != kSlerpAngleFloats * intervals)
                    return;
                for (std::size_t k = 0; k < intervals; ++k)
                    if (sampler.slerpAngles[kSlerpAngleFloats * k + 3] == 0) return;  // slerp
                plan.rotationChannels.push_back(static_cast<std::uint32_t>(c));
                break;
            }
            case AnimatedProperty::Translation:
            case AnimatedProperty::Scale:
                if (sampler.components != 3) return;
                plan.otherChannels.push_back(static_cast<std::uint32_t>(c));
                break;
            case AnimatedProperty::Weights:
                return;
        }
        const auto node = static_cast<std::uint32_t>(channel.node);
        if (std::find(plan.nodes.begin(), plan.nodes.end(), node) == plan.nodes.end())
            plan.nodes.push_back(node);
    }
    if (plan.nodes.empty()) return;
    constexpr std::size_t lanes = SharedKeyRotations::kLanes;
    const std::size_t keys = clip.samplers.front().times.size();
    const std::size_t groups = plan.groups();
    plan.keys.assign(keys * groups * 4 * lanes, 0.0f);
    plan.corrections.assign((keys - 1) * groups * 3 * lanes, 0.0f);
    for (std::size_t g = 0; g < groups; ++g) {
        for (std::size_t lane = 0; lane < lanes; ++lane) {
            const std::size_t r = g * lanes + lane;
            for (std::size_t k = 0; k < keys; ++k) {
                float* key = plan.keys.data() + (k * groups + g) * 4 * lanes;
                if (r >= plan.rotationChannels.size()) {
                    key[3 * lanes + lane] = 1;  // the identity, never stored
                    continue;
                }
                const AnimationChannel& channel = clip.channels[plan.rotationChannels[r]];
                const AnimationSampler& sampler =
                    clip.samplers[static_cast<std::size_t>(channel.sampler)];
                for (std::size_t c = 0; c < 4; ++c)
                    key[c * lanes + lane] = sampler.values[k * 4 + c];
                if (k + 1 == keys) continue;
                float* correction = plan.corrections.data() + (k * groups + g) * 3 * lanes;
                for (std::size_t c = 0; c < 3; ++c)
                    correction[c * lanes + lane] = sampler.slerpAngles[kSlerpAngleFloats * k + c];
            }
        }
    }
    clip.sharedRotations = std::move(plan);
}

}  // namespace

void markSharedKeyTimes(AnimationClip& clip) {
    clip.linearSharedTimes = false;
    clip.sharedRotations = {};
    if (clip.samplers.empty()) return;
    const std::vector<float>& times = clip.samplers.front().times;
    if (times.size() < 2) return;
    for (const AnimationSampler& sampler : clip.samplers) {
        if (sampler.interpolation != Interpolation::Linear ||
            sampler.times.size() != times.size() ||
            !std::equal(times.begin(), times.end(), sampler.times.begin()))
            return;
    }
    clip.linearSharedTimes = true;
    buildSharedKeyRotations(clip);
}

float clipTime(float time, float duration, bool loop) {
    if (!(duration > 0)) return 0;
    if (loop) {
        // Already in [0, duration) (a looping player keeps its time wrapped): fmod would
        // return it unchanged (fmod is exact), without its cost.
        if (time >= 0 && time < duration) return time;
        const float wrapped = std::fmod(time, duration);
        return wrapped < 0 ? wrapped + duration : wrapped;
    }
    return std::clamp(time, 0.0f, duration);
}

void sampleAnimation(const AnimationSampler& sampler, AnimatedProperty property, float time,
                     std::span<float> out) {
    std::uint32_t cursor = 0;
    sampleAnimation(sampler, property, time, out, cursor);
}

void sampleAnimationUnnormalised(const AnimationSampler& sampler, AnimatedProperty property,
                                 float time, std::span<float> out, std::uint32_t& cursor) {
    const std::size_t n = sampler.components;
    const std::size_t keys = sampler.times.size();
    const bool cubic = sampler.interpolation == Interpolation::CubicSpline;
    const std::size_t stride = cubic ? 3 * n : n;
    const std::size_t valueOffset = cubic ? n : 0;  // CUBICSPLINE: skip the in-tangent
    const float* values = sampler.values.data();
    // The cursor's interval (forward playback: nearly always), else the search.
    const float* times = sampler.times.data();
    std::size_t k = cursor;
    if (!(k + 1 < keys && times[k] <= time && time < times[k + 1] && time > times[0]))
        k = keyIntervalAt(sampler.times, time, cursor);
    const bool clamped = keys < 2 || time <= sampler.times.front() || k + 1 >= keys;
    if (clamped || sampler.interpolation == Interpolation::Step) {
        std::copy_n(values + k * stride + valueOffset, n, out.begin());
        return;
    }
    const float t0 = sampler.times[k];
    const float interval = sampler.times[k + 1] - t0;
    const float t = (time - t0) / interval;
    const float* a = values + k * stride;
    const float* b = values + (k + 1) * stride;
    if (sampler.interpolation == Interpolation::Linear) {
        if (property == AnimatedProperty::Rotation) {
            const bool cached = sampler.slerpAngles.size() == kSlerpAngleFloats * (keys - 1);
            slerp(a, b, t, out.data(),
                  cached ? sampler.slerpAngles.data() + kSlerpAngleFloats * k : nullptr);
        } else {
            for (std::size_t c = 0; c < n; ++c)
                out[c] = a[c] + (b[c] - a[c]) * t;
        }
        return;
    }
    // Hermite: p(t) = h00 v_k + h10 d b_k + h01 v_k+1 + h11 d a_k+1, with d the key interval,
    // b_k the out-tangent of key k and a_k+1 the in-tangent of key k+1.
    const float t2 = t * t;
    const float t3 = t2 * t;
    const float h00 = 2 * t3 - 3 * t2 + 1;
    const float h10 = (t3 - 2 * t2 + t) * interval;
    const float h01 = -2 * t3 + 3 * t2;
    const float h11 = (t3 - t2) * interval;
    for (std::size_t c = 0; c < n; ++c) {
        const float valueA = a[n + c];
        const float outTangentA = a[2 * n + c];
        const float inTangentB = b[c];
        const float valueB = b[n + c];
        out[c] = h00 * valueA + h10 * outTangentA + h01 * valueB + h11 * inTangentB;
    }
}

void sampleAnimation(const AnimationSampler& sampler, AnimatedProperty property, float time,
                     std::span<float> out, std::uint32_t& cursor) {
    sampleAnimationUnnormalised(sampler, property, time, out, cursor);
    if (property == AnimatedProperty::Rotation) normalizeQuaternion(out.data());
}

void normalizeQuaternions(std::span<float* const> quaternions) {
    std::size_t i = 0;
#if defined(__SSE2__)
    // Four at a time, structure of arrays: per lane the same squares summed in the same order,
    // the same square root and the same divisions as normalizeQuaternion (same values), one
    // sqrtps and four divps for four quaternions.
    for (; i + 4 <= quaternions.size(); i += 4) {
        __m128 x = _mm_loadu_ps(quaternions[i]), y = _mm_loadu_ps(quaternions[i + 1]);
        __m128 z = _mm_loadu_ps(quaternions[i + 2]), w = _mm_loadu_ps(quaternions[i + 3]);
        _MM_TRANSPOSE4_PS(x, y, z, w);
        const __m128 sum =
            _mm_add_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(x, x), _mm_mul_ps(y, y)), _mm_mul_ps(z, z)),
                       _mm_mul_ps(w, w));
        const __m128 length = _mm_sqrt_ps(sum);
        const __m128 usable = _mm_cmpgt_ps(length, _mm_set1_ps(1e-20f));
        // Too short to normalise: the identity (0, 0, 0, 1).
        auto pick = [&](__m128 normalised, __m128 fallback) {
            return _mm_or_ps(_mm_and_ps(usable, normalised), _mm_andnot_ps(usable, fallback));
        };
        x = pick(_mm_div_ps(x, length), _mm_setzero_ps());
        y = pick(_mm_div_ps(y, length), _mm_setzero_ps());
        z = pick(_mm_div_ps(z, length), _mm_setzero_ps());
        w = pick(_mm_div_ps(w, length), _mm_set1_ps(1.0f));
        _MM_TRANSPOSE4_PS(x, y, z, w);
        _mm_storeu_ps(quaternions[i], x);
        _mm_storeu_ps(quaternions[i + 1], y);
        _mm_storeu_ps(quaternions[i + 2], z);
        _mm_storeu_ps(quaternions[i + 3], w);
    }
#endif
    for (; i < quaternions.size(); ++i)
        normalizeQuaternion(quaternions[i]);
}

}  // namespace candela::content
