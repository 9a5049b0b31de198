#pragma once
// Typed reads from tinygltf::Value (extensions and extras), rejecting non-finite numbers.
#include <tiny_gltf.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>

namespace candela::content::gltf {

// True when `value` is a number representable as a finite float.
inline bool toFiniteFloat(double value, float& out) {
    if (!std::isfinite(value) || std::fabs(value) > std::numeric_limits<float>::max()) return false;
    out = static_cast<float>(value);
    return true;
}

inline const tinygltf::Value* member(const tinygltf::Value& object, const char* key) {
    if (!object.IsObject() || !object.Has(key)) return nullptr;
    return &object.Get(key);
}

// Reads object[key] as a finite number; returns false (leaving `out`) when absent or invalid.
inline bool readNumber(const tinygltf::Value& object, const char* key, float& out) {
    const tinygltf::Value* v = member(object, key);
    return v != nullptr && v->IsNumber() && toFiniteFloat(v->GetNumberAsDouble(), out);
}

template <std::size_t N>
bool readNumbers(const tinygltf::Value& object, const char* key, std::array<float, N>& out) {
    const tinygltf::Value* v = member(object, key);
    if (v == nullptr || !v->IsArray() || v->ArrayLen() != N) return false;
    std::array<float, N> values{};
    for (std::size_t i = 0; i < N; ++i) {
        const tinygltf::Value& e = v->Get(static_cast<int>(i));
        if (!e.IsNumber() || !toFiniteFloat(e.GetNumberAsDouble(), values[i])) return false;
    }
    out = values;
    return true;
}

inline bool readString(const tinygltf::Value& object, const char* key, std::string& out) {
    const tinygltf::Value* v = member(object, key);
    if (v == nullptr || !v->IsString()) return false;
    out = v->Get<std::string>();
    return true;
}

// Copies a std::vector<double> of exactly N finite entries into `out`.
template <std::size_t N>
bool copyFactors(const std::vector<double>& in, std::array<float, N>& out) {
    if (in.size() != N) return false;
    std::array<float, N> values{};
    for (std::size_t i = 0; i < N; ++i) {
        if (!toFiniteFloat(in[i], values[i])) return false;
    }
    out = values;
    return true;
}

}  // namespace candela::content::gltf
