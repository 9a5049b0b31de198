#pragma once
// Matrix products on whole columns (SSE2 where the target has it, the same sums in the same
// order otherwise, so both give identical results): the hot steps of transform propagation
// and of the animation's skeleton pass, which must agree bit for bit.
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <candela/ecs/transform_math.h>

namespace candela::ecs {

#if defined(__SSE2__)
// parent * local (local affine, 16 floats, column-major) as four column registers: what
// multiplyByAffine stores, for callers that go on computing with the columns (the skin bounds)
// instead of reloading them.
struct MatrixColumns {
    __m128 c0, c1, c2, c3;
};
inline MatrixColumns multiplyByAffineColumns(const Mat4& parent, const float* local) noexcept {
    const __m128 p0 = _mm_loadu_ps(parent.m + 0);
    const __m128 p1 = _mm_loadu_ps(parent.m + 4);
    const __m128 p2 = _mm_loadu_ps(parent.m + 8);
    const __m128 p3 = _mm_loadu_ps(parent.m + 12);
    // parent * (x, y, z, 0) for one column of the local matrix.
    auto transform = [&](const float* column) {
        const __m128 l = _mm_loadu_ps(column);
        return _mm_add_ps(_mm_add_ps(_mm_mul_ps(p0, _mm_shuffle_ps(l, l, _MM_SHUFFLE(0, 0, 0, 0))),
                                     _mm_mul_ps(p1, _mm_shuffle_ps(l, l, _MM_SHUFFLE(1, 1, 1, 1)))),
                          _mm_mul_ps(p2, _mm_shuffle_ps(l, l, _MM_SHUFFLE(2, 2, 2, 2))));
    };
    return {transform(local + 0), transform(local + 4), transform(local + 8),
            _mm_add_ps(transform(local + 12), p3)};  // w = 1
}
#endif

// out = parent * local, where local (16 floats, column-major) is affine (last row 0 0 0 1). The hot
// step of propagation: with SSE2 it is 12 broadcasts, 12 multiplies and 9 adds on whole columns.
inline void multiplyByAffine(const Mat4& parent, const float* local, Mat4& out) noexcept {
#if defined(__SSE2__)
    const MatrixColumns product = multiplyByAffineColumns(parent, local);
    _mm_storeu_ps(out.m + 0, product.c0);
    _mm_storeu_ps(out.m + 4, product.c1);
    _mm_storeu_ps(out.m + 8, product.c2);
    _mm_storeu_ps(out.m + 12, product.c3);
#else
    for (int c = 0; c < 4; ++c) {
        const float l0 = local[4 * c], l1 = local[4 * c + 1], l2 = local[4 * c + 2];
        for (int i = 0; i < 4; ++i) {
            out.m[4 * c + i] = parent.m[i] * l0 + parent.m[4 + i] * l1 + parent.m[8 + i] * l2 +
                               (c == 3 ? parent.m[12 + i] : 0.0f);
        }
    }
#endif
}

inline void multiplyByAffine(const Mat4& parent, const Mat4& local, Mat4& out) noexcept {
    multiplyByAffine(parent, local.m, out);
}

// out = a * b for any column-major 4x4 b (16 floats), in Mat4's operator* order.
inline void multiplyMatrices(const Mat4& a, const float* b, Mat4& out) noexcept {
#if defined(__SSE2__)
    const __m128 a0 = _mm_loadu_ps(a.m + 0);
    const __m128 a1 = _mm_loadu_ps(a.m + 4);
    const __m128 a2 = _mm_loadu_ps(a.m + 8);
    const __m128 a3 = _mm_loadu_ps(a.m + 12);
    for (int c = 0; c < 4; ++c) {
        const __m128 col = _mm_loadu_ps(b + 4 * c);
        const __m128 r = _mm_add_ps(
            _mm_add_ps(
                _mm_add_ps(_mm_mul_ps(a0, _mm_shuffle_ps(col, col, _MM_SHUFFLE(0, 0, 0, 0))),
                           _mm_mul_ps(a1, _mm_shuffle_ps(col, col, _MM_SHUFFLE(1, 1, 1, 1)))),
                _mm_mul_ps(a2, _mm_shuffle_ps(col, col, _MM_SHUFFLE(2, 2, 2, 2)))),
            _mm_mul_ps(a3, _mm_shuffle_ps(col, col, _MM_SHUFFLE(3, 3, 3, 3))));
        _mm_storeu_ps(out.m + 4 * c, r);
    }
#else
    for (int c = 0; c < 4; ++c) {
        const float b0 = b[c * 4 + 0], b1 = b[c * 4 + 1], b2 = b[c * 4 + 2], b3 = b[c * 4 + 3];
        for (int i = 0; i < 4; ++i)
            out.m[c * 4 + i] = a.m[i] * b0 + a.m[4 + i] * b1 + a.m[8 + i] * b2 + a.m[12 + i] * b3;
    }
#endif
}

// out = parent * Mat4::fromTranslationRotationScale(t, q, s) (parent affine, or null for the
// identity), the same values as building the local matrix and calling multiplyByAffine; the
// local columns are formed in registers, not stored and reloaded (a scalar store read back
// as a vector stalls store forwarding).
inline void composeWorld(const Mat4* parent, Vec3 t, Quat q, Vec3 s, Mat4& out) noexcept {
    const float xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
    const float xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z;
    const float wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
    const float l[12] = {(1 - 2 * (yy + zz)) * s.x,
                         2 * (xy + wz) * s.x,
                         2 * (xz - wy) * s.x,
                         2 * (xy - wz) * s.y,
                         (1 - 2 * (xx + zz)) * s.y,
                         2 * (yz + wx) * s.y,
                         2 * (xz + wy) * s.z,
                         2 * (yz - wx) * s.z,
                         (1 - 2 * (xx + yy)) * s.z,
                         t.x,
                         t.y,
                         t.z};
    if (parent == nullptr) {
        out = Mat4{
            {l[0], l[1], l[2], 0, l[3], l[4], l[5], 0, l[6], l[7], l[8], 0, l[9], l[10], l[11], 1}};
        return;
    }
#if defined(__SSE2__)
    const __m128 p0 = _mm_loadu_ps(parent->m + 0);
    const __m128 p1 = _mm_loadu_ps(parent->m + 4);
    const __m128 p2 = _mm_loadu_ps(parent->m + 8);
    const __m128 p3 = _mm_loadu_ps(parent->m + 12);
    auto column = [&](int c) {
        return _mm_add_ps(_mm_add_ps(_mm_mul_ps(p0, _mm_set1_ps(l[3 * c])),
                                     _mm_mul_ps(p1, _mm_set1_ps(l[3 * c + 1]))),
                          _mm_mul_ps(p2, _mm_set1_ps(l[3 * c + 2])));
    };
    _mm_storeu_ps(out.m + 0, column(0));
    _mm_storeu_ps(out.m + 4, column(1));
    _mm_storeu_ps(out.m + 8, column(2));
    _mm_storeu_ps(out.m + 12, _mm_add_ps(column(3), p3));
#else
    for (int c = 0; c < 4; ++c) {
        for (int i = 0; i < 4; ++i) {
            out.m[4 * c + i] = parent->m[i] * l[3 * c] + parent->m[4 + i] * l[3 * c + 1] +
                               parent->m[8 + i] * l[3 * c + 2] +
                               (c == 3 ? parent->m[12 + i] : 0.0f);
        }
    }
#endif
}

}  // namespace candela::ecs
