#pragma once
// The little vector math transforms need. Layouts match GLM (Vec3 = 3 floats, Quat = x, y, z,
// w, Mat4 = 16 floats column-major, element (row r, column c) at m[c * 4 + r]) so the renderer
// can memcpy these into glm types or GPU buffers.
#include <cmath>
#include <type_traits>

namespace candela::ecs {

struct Vec3 {
    float x = 0.0f;
    float y = 0.0f;
    float z = 0.0f;

    friend constexpr Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
    friend constexpr Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
    friend constexpr Vec3 operator*(Vec3 a, float s) { return {a.x * s, a.y * s, a.z * s}; }
    friend constexpr Vec3 operator*(float s, Vec3 a) { return a * s; }
    constexpr Vec3& operator+=(Vec3 b) { return *this = *this + b; }
    constexpr Vec3& operator-=(Vec3 b) { return *this = *this - b; }
    constexpr Vec3& operator*=(float s) { return *this = *this * s; }
    friend constexpr bool operator==(Vec3, Vec3) = default;
};

constexpr float dot(Vec3 a, Vec3 b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
constexpr Vec3 cross(Vec3 a, Vec3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline float length(Vec3 a) {
    return std::sqrt(dot(a, a));
}

struct Quat {
    float x = 0.0f;
    float y = 0.0f;
    float z = 0.0f;
    float w = 1.0f;

    static Quat fromAxisAngle(Vec3 axis, float radians) {
        const float len = length(axis);
        if (len == 0.0f) return {};
        const float s = std::sin(radians * 0.5f) / len;
        return {axis.x * s, axis.y * s, axis.z * s, std::cos(radians * 0.5f)};
    }
    // Hamilton product: (a * b) rotates by b first, then by a (as GLM).
    friend constexpr Quat operator*(Quat a, Quat b) {
        return {a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
                a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
                a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w,
                a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z};
    }
    friend constexpr bool operator==(Quat, Quat) = default;
};

constexpr Quat conjugate(Quat q) {
    return {-q.x, -q.y, -q.z, q.w};
}
inline Quat normalize(Quat q) {
    const float len = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
    if (len == 0.0f) return {};
    const float inv = 1.0f / len;
    return {q.x * inv, q.y * inv, q.z * inv, q.w * inv};
}
// Rotates v by unit quaternion q.
constexpr Vec3 rotate(Quat q, Vec3 v) {
    const Vec3 u{q.x, q.y, q.z};
    const Vec3 t = cross(u, v) * 2.0f;
    return v + t * q.w + cross(u, t);
}

struct Mat4 {
    float m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

    static constexpr Mat4 identity() { return {}; }
    constexpr float& operator()(int row, int column) { return m[column * 4 + row]; }
    constexpr float operator()(int row, int column) const { return m[column * 4 + row]; }

    // Translation * Rotation * Scale, the order glTF nodes and LocalTransform use.
    static constexpr Mat4 fromTranslationRotationScale(Vec3 t, Quat q, Vec3 s) {
        const float xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
        const float xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z;
        const float wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
        return Mat4{{(1 - 2 * (yy + zz)) * s.x, 2 * (xy + wz) * s.x, 2 * (xz - wy) * s.x, 0,
                     2 * (xy - wz) * s.y, (1 - 2 * (xx + zz)) * s.y, 2 * (yz + wx) * s.y, 0,
                     2 * (xz + wy) * s.z, 2 * (yz - wx) * s.z, (1 - 2 * (xx + yy)) * s.z, 0, t.x,
                     t.y, t.z, 1}};
    }
    static constexpr Mat4 translation(Vec3 t) {
        return Mat4{{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, t.x, t.y, t.z, 1}};
    }

    friend constexpr Mat4 operator*(const Mat4& a, const Mat4& b) {
        Mat4 r;
        for (int c = 0; c < 4; ++c) {
            const float b0 = b.m[c * 4 + 0], b1 = b.m[c * 4 + 1];
            const float b2 = b.m[c * 4 + 2], b3 = b.m[c * 4 + 3];
            for (int i = 0; i < 4; ++i) {
                r.m[c * 4 + i] = a.m[i] * b0 + a.m[4 + i] * b1 + a.m[8 + i] * b2 + a.m[12 + i] * b3;
            }
        }
        return r;
    }
    friend constexpr bool operator==(const Mat4& a, const Mat4& b) {
        for (int i = 0; i < 16; ++i) {
            if (a.m[i] != b.m[i]) return false;
        }
        return true;
    }

    constexpr Vec3 transformPoint(Vec3 p) const {
        return {m[0] * p.x + m[4] * p.y + m[8] * p.z + m[12],
                m[1] * p.x + m[5] * p.y + m[9] * p.z + m[13],
                m[2] * p.x + m[6] * p.y + m[10] * p.z + m[14]};
    }
    constexpr Vec3 transformVector(Vec3 v) const {
        return {m[0] * v.x + m[4] * v.y + m[8] * v.z, m[1] * v.x + m[5] * v.y + m[9] * v.z,
                m[2] * v.x + m[6] * v.y + m[10] * v.z};
    }
    constexpr Vec3 translationPart() const { return {m[12], m[13], m[14]}; }
};

// parent * fromTranslationRotationScale(t, q, s), skipping the products with the local
// matrix's constant last row. This is the inner step of transform propagation.
constexpr Mat4 composeWithLocal(const Mat4& parent, Vec3 t, Quat q, Vec3 s) {
    const Mat4 local = Mat4::fromTranslationRotationScale(t, q, s);
    Mat4 r;
    for (int c = 0; c < 3; ++c) {
        const float l0 = local.m[c * 4 + 0], l1 = local.m[c * 4 + 1], l2 = local.m[c * 4 + 2];
        for (int i = 0; i < 4; ++i) {
            r.m[c * 4 + i] = parent.m[i] * l0 + parent.m[4 + i] * l1 + parent.m[8 + i] * l2;
        }
    }
    for (int i = 0; i < 4; ++i) {
        r.m[12 + i] =
            parent.m[i] * t.x + parent.m[4 + i] * t.y + parent.m[8 + i] * t.z + parent.m[12 + i];
    }
    return r;
}

static_assert(sizeof(Vec3) == 12 && std::is_standard_layout_v<Vec3>);
static_assert(sizeof(Quat) == 16 && std::is_standard_layout_v<Quat>);
static_assert(sizeof(Mat4) == 64 && std::is_standard_layout_v<Mat4>);

}  // namespace candela::ecs
