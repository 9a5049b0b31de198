#pragma once
// IEEE 754 binary16 emulation on the CPU, for the fp16 report: Karis 2014's ("Physically Based
// Shading on Mobile") mobile shaders compute in `half`. roundToHalf() rounds a float to the nearest
// binary16 value (ties to even, gradual underflow to subnormals, overflow to infinity); Half rounds
// after every operation.
//
// Doing each operation in float and then rounding is correctly rounded binary16 arithmetic: for
// +, -, *, / and sqrt, double rounding is innocuous when the wider format has at least 2p + 2
// significand bits (Figueroa 1995); float has 24 >= 2 * 11 + 2. Transcendentals (exp2) are
// computed in float and rounded once, i.e. as well as a half unit can do, which makes the
// report optimistic about real mediump hardware, never pessimistic.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace candela::stability {

constexpr float kHalfMax = 65504.0f;
constexpr float kHalfMinNormal = 6.103515625e-05f;            // 2^-14
constexpr float kHalfMinSubnormal = 5.9604644775390625e-08f;  // 2^-24
constexpr float kHalfEpsilon = 9.765625e-04f;                 // 2^-10, spacing just above 1

inline float roundToHalf(float x) {
    if (std::isnan(x)) return x;
    const float magnitude = std::fabs(x);
    // 65504 is the largest half; 65520 is the midpoint to the next (2^16) and ties to even,
    // i.e. up, so everything from there overflows.
    if (magnitude >= 65520.0f) return std::copysign(std::numeric_limits<float>::infinity(), x);
    int exponent = 0;
    std::frexp(magnitude, &exponent);  // magnitude in [2^(exponent-1), 2^exponent)
    // Halves have 10 fraction bits; below 2^-14 the spacing stays 2^-24 (subnormals).
    const int quantumExponent = std::max(exponent - 1, -14) - 10;
    const float quantum = std::ldexp(1.0f, quantumExponent);
    // magnitude / quantum < 2^11 is exact, and nearbyint rounds ties to even.
    const float rounded = std::nearbyint(magnitude / quantum) * quantum;
    return std::copysign(rounded, x);
}

inline bool isHalfSubnormalOrZero(float h) {
    return std::fabs(h) < kHalfMinNormal;
}

// A binary16 value in a float; every operation rounds its result to binary16.
struct Half {
    float value = 0.0f;

    Half() = default;
    Half(float v) : value(roundToHalf(v)) {}  // NOLINT: implicit, like a half literal
    explicit operator float() const { return value; }
};

inline Half operator+(Half a, Half b) {
    return Half(a.value + b.value);
}
inline Half operator-(Half a, Half b) {
    return Half(a.value - b.value);
}
inline Half operator*(Half a, Half b) {
    return Half(a.value * b.value);
}
inline Half operator/(Half a, Half b) {
    return Half(a.value / b.value);
}
inline Half operator-(Half a) {
    return Half(-a.value);
}
inline bool operator<(Half a, Half b) {
    return a.value < b.value;
}
inline bool operator>(Half a, Half b) {
    return a.value > b.value;
}

inline Half min(Half a, Half b) {
    return b.value < a.value ? b : a;
}
inline Half max(Half a, Half b) {
    return a.value < b.value ? b : a;
}
inline Half saturate(Half x) {
    return min(max(x, Half(0.0f)), Half(1.0f));
}
inline Half exp2(Half x) {
    return Half(std::exp2(x.value));
}
inline Half sqrt(Half x) {
    return Half(std::sqrt(x.value));
}

}  // namespace candela::stability
