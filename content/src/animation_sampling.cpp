#include "candela/content/animation_sampling.h"

#include <algorithm>
#include <cmath>

namespace candela::content {
namespace {

[[gnu::always_inline]] inline void normalizeQuaternion(std::span<float> q) {
    const float length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (length > 1e-20f) {
        const float inverse = 1.0f / length;
        for (int c = 0; c < 4; ++c)
            q[static_cast<std::size_t>(c)] *= inverse;
    } else {
        q[0] = q[1] = q[2] = 0;
        q[3] = 1;
    }
}

// sin(t theta) / sin(theta) as a power series in x - 1, x = cos(theta) (Eberly, "A Fast and
// Accurate Algorithm for Computing SLERP", 2011): c_0 = t, c_i = c_(i-1) (t^2 - i^2) /
// (i (2i + 1)) (x - 1). The terms shrink by at least (1 - x) / 2 each, so eight of them are
// within 7e-9 of the trigonometric value for x >= 0.75 (theta <= 41 degrees, any key interval
// a clip samples at a usable rate) with no acos or sine; both weights are evaluated together.
constexpr float kSeriesMinCos = 0.75f;
constexpr int kSeriesTerms = 8;
// 1 / (i (2i + 1)) and i^2 for i = 1..7: multiplies, not divisions, in the loop.
constexpr float kSeriesScale[kSeriesTerms] = {0,         1.0f / 3,  1.0f / 10, 1.0f / 21,
                                              1.0f / 36, 1.0f / 55, 1.0f / 78, 1.0f / 105};
constexpr float kSeriesSquare[kSeriesTerms] = {0, 1, 4, 9, 16, 25, 36, 49};

void seriesWeights(float x, float t, float& wa, float& wb) {
    const float d = x - 1;
    const float u = 1 - t;
    // Each term is under |d| / 2 times the one before: fewer terms reach the same 1e-8 when
    // the keys are close (the usual case).
    const int terms = d > -0.002f ? 3 : d > -0.05f ? 5 : kSeriesTerms;
    float ca = u, cb = t;
    wa = u;
    wb = t;
    const float uu = u * u, tt = t * t;
    for (int i = 1; i < terms; ++i) {
        const float scale = d * kSeriesScale[i];
        ca *= (uu - kSeriesSquare[i]) * scale;
        cb *= (tt - kSeriesSquare[i]) * scale;
        wa += ca;
        wb += cb;
    }
}

// Shortest-arc spherical interpolation: the series above for the usual small key-to-key
// angles, the trigonometric form for wide ones.
void slerp(const float* a, const float* b, float t, std::span<float> out) {
    float cosTheta = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
    const float sign = cosTheta < 0 ? -1.0f : 1.0f;
    cosTheta = std::min(cosTheta * sign, 1.0f);
    float wa, wb;
    if (cosTheta >= kSeriesMinCos) {
        seriesWeights(cosTheta, t, wa, wb);
    } else {
        const float theta = std::acos(cosTheta);
        const float sinTheta = std::sin(theta);
        wa = std::sin((1 - t) * theta) / sinTheta;
        wb = std::sin(t * theta) / sinTheta;
    }
    for (std::size_t c = 0; c < 4; ++c)
        out[c] = wa * a[c] + sign * wb * b[c];
    normalizeQuaternion(out);
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

float clipTime(float time, float duration, bool loop) {
    if (!(duration > 0)) return 0;
    if (loop) {
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

void sampleAnimation(const AnimationSampler& sampler, AnimatedProperty property, float time,
                     std::span<float> out, std::uint32_t& cursor) {
    const std::size_t n = sampler.components;
    const std::size_t keys = sampler.times.size();
    const bool cubic = sampler.interpolation == Interpolation::CubicSpline;
    const std::size_t stride = cubic ? 3 * n : n;
    const std::size_t valueOffset = cubic ? n : 0;  // CUBICSPLINE: skip the in-tangent
    const float* values = sampler.values.data();
    const std::size_t k = keyIntervalAt(sampler.times, time, cursor);
    const bool clamped = keys < 2 || time <= sampler.times.front() || k + 1 >= keys;
    if (clamped || sampler.interpolation == Interpolation::Step) {
        std::copy_n(values + k * stride + valueOffset, n, out.begin());
        if (property == AnimatedProperty::Rotation) normalizeQuaternion(out);
        return;
    }
    const float t0 = sampler.times[k];
    const float interval = sampler.times[k + 1] - t0;
    const float t = (time - t0) / interval;
    const float* a = values + k * stride;
    const float* b = values + (k + 1) * stride;
    if (sampler.interpolation == Interpolation::Linear) {
        if (property == AnimatedProperty::Rotation) {
            slerp(a, b, t, out);
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
    if (property == AnimatedProperty::Rotation) normalizeQuaternion(out);
}

}  // namespace candela::content
