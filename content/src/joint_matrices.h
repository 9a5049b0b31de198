#pragma once
// Skin joint matrices and deformed bounds from the joints' world matrices: shared by the
// skeleton pass (worlds it has just computed) and updateSkins (worlds after propagation).
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "candela/content/animation.h"
#include "candela/content/components/animation.h"
#include "candela/ecs/affine_multiply.h"

namespace candela::content {

// Inverse of an affine matrix (last row 0 0 0 1), through the 3x3 adjugate.
ecs::Mat4 affineInverse(const ecs::Mat4& m);

// Asked of every skin's mesh every frame: four column compares, not sixteen branches.
inline bool isIdentity(const ecs::Mat4& m) {
#if defined(__SSE2__)
    const __m128 c0 = _mm_cmpeq_ps(_mm_loadu_ps(m.m + 0), _mm_setr_ps(1, 0, 0, 0));
    const __m128 c1 = _mm_cmpeq_ps(_mm_loadu_ps(m.m + 4), _mm_setr_ps(0, 1, 0, 0));
    const __m128 c2 = _mm_cmpeq_ps(_mm_loadu_ps(m.m + 8), _mm_setr_ps(0, 0, 1, 0));
    const __m128 c3 = _mm_cmpeq_ps(_mm_loadu_ps(m.m + 12), _mm_setr_ps(0, 0, 0, 1));
    return _mm_movemask_ps(_mm_and_ps(_mm_and_ps(c0, c1), _mm_and_ps(c2, c3))) == 0xF;
#else
    for (int i = 0; i < 16; ++i)
        if (m.m[i] != (i % 5 == 0 ? 1.0f : 0.0f)) return false;
    return true;
#endif
}

// Last row 0 0 0 1 (glTF's inverse bind matrices are; a file may still hold another).
inline bool isAffine(const Matrix4& m) {
    return m[3] == 0 && m[7] == 0 && m[11] == 0 && m[15] == 1;
}

// Per joint j: toMesh * world(j) * inverse bind (the identity where world(j) is null: the
// joint is not shown), written over last frame's in place (no allocation once sized), and
// the deformed mesh's bounds from each joint's bind-space box.
// `inverseBindsAffine`: the caller knows every inverse bind matrix is affine (false: each is
// tested).
template <class JointWorld>
void buildJointMatrices(Skin& skin, const SkinData& data, const ecs::Mat4& toMesh,
                        JointWorld&& world, bool inverseBindsAffine = false) {
    if (skin.jointMatrices.size() != data.joints.size())
        skin.jointMatrices.assign(data.joints.size(), ecs::Mat4::identity());
    constexpr float kInf = std::numeric_limits<float>::infinity();
    ecs::Vec3 lo{kInf, kInf, kInf}, hi{-kInf, -kInf, -kInf};
    ecs::Mat4 toJoint;
#if defined(__SSE2__)
    __m128 low = _mm_set1_ps(kInf), high = _mm_set1_ps(-kInf);
#endif
    // A mesh at its world's origin (a character at the root, as the file places it) makes
    // toMesh the identity, whose product changes no value (only a zero's sign): skipped.
    const bool meshAtOrigin = isIdentity(toMesh);
    const std::array<float, 6>* jointBoxes = skin.jointBounds ? skin.jointBounds->data() : nullptr;
    const std::size_t jointBoxCount = skin.jointBounds ? skin.jointBounds->size() : 0;
    // Held in locals: the SIMD stores below may alias anything, so members read through
    // `skin` and `data` would be reloaded every joint.
    const std::size_t jointCount = data.joints.size();
    ecs::Mat4* const out = skin.jointMatrices.data();
    const Matrix4* const inverseBinds = data.inverseBindMatrices.data();
#if defined(__SSE2__)
    auto columnsOf = [](const ecs::Mat4& matrix) {
        return ecs::MatrixColumns{_mm_loadu_ps(matrix.m), _mm_loadu_ps(matrix.m + 4),
                                  _mm_loadu_ps(matrix.m + 8), _mm_loadu_ps(matrix.m + 12)};
    };
#endif
    for (std::size_t j = 0; j < jointCount; ++j) {
        const ecs::Mat4* jointWorld = world(j);
#if defined(__SSE2__)
        ecs::MatrixColumns m;
#endif
        if (jointWorld) {
            const ecs::Mat4* meshFromJoint = jointWorld;
            if (!meshAtOrigin) {
                ecs::multiplyByAffine(toMesh, *jointWorld, toJoint);
                meshFromJoint = &toJoint;
            }
            // An affine inverse bind matrix (glTF's are; a file may still hold another) skips
            // the products with its last row, which add exact zeros (same values).
            const Matrix4& inverseBind = inverseBinds[j];
            if (inverseBindsAffine || isAffine(inverseBind)) {
#if defined(__SSE2__)
                // The product stays in registers for the bounds below (no store-to-load trip).
                m = ecs::multiplyByAffineColumns(*meshFromJoint, inverseBind.data());
                _mm_storeu_ps(out[j].m + 0, m.c0);
                _mm_storeu_ps(out[j].m + 4, m.c1);
                _mm_storeu_ps(out[j].m + 8, m.c2);
                _mm_storeu_ps(out[j].m + 12, m.c3);
#else
                ecs::multiplyByAffine(*meshFromJoint, inverseBind.data(), out[j]);
#endif
            } else {
                ecs::multiplyMatrices(*meshFromJoint, inverseBind.data(), out[j]);
#if defined(__SSE2__)
                m = columnsOf(out[j]);
#endif
            }
        } else {
            out[j] = ecs::Mat4{};
#if defined(__SSE2__)
            m = columnsOf(out[j]);
#endif
        }
        if (j >= jointBoxCount) continue;
        const std::array<float, 6>& box = jointBoxes[j];
        if (!(box[3] >= 0)) continue;  // the joint moves no vertex
        // The moved box's bounds from its centre and half size (Arvo): the centre moved by
        // the matrix, the half size by its absolute values; the same box as moving all 8
        // corners, at a quarter of the work.
        const float* centreIn = box.data();
        const float* half = box.data() + 3;
#if defined(__SSE2__)
        // Whole columns, in transformPoint's and the scalar form's order (same results).
        const __m128 c0 = m.c0, c1 = m.c1, c2 = m.c2, c3 = m.c3;
        const __m128 centre =
            _mm_add_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(c0, _mm_set1_ps(centreIn[0])),
                                             _mm_mul_ps(c1, _mm_set1_ps(centreIn[1]))),
                                  _mm_mul_ps(c2, _mm_set1_ps(centreIn[2]))),
                       c3);
        const __m128 sign = _mm_set1_ps(-0.0f);
        const __m128 reach =
            _mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_andnot_ps(sign, c0), _mm_set1_ps(half[0])),
                                  _mm_mul_ps(_mm_andnot_ps(sign, c1), _mm_set1_ps(half[1]))),
                       _mm_mul_ps(_mm_andnot_ps(sign, c2), _mm_set1_ps(half[2])));
        low = _mm_min_ps(low, _mm_sub_ps(centre, reach));
        high = _mm_max_ps(high, _mm_add_ps(centre, reach));
#else
        const ecs::Mat4& m = out[j];
        const ecs::Vec3 centre = m.transformPoint({centreIn[0], centreIn[1], centreIn[2]});
        float reach[3];
        for (int row = 0; row < 3; ++row) {
            reach[row] = std::fabs(m(row, 0)) * half[0] + std::fabs(m(row, 1)) * half[1] +
                         std::fabs(m(row, 2)) * half[2];
        }
        lo = {std::min(lo.x, centre.x - reach[0]), std::min(lo.y, centre.y - reach[1]),
              std::min(lo.z, centre.z - reach[2])};
        hi = {std::max(hi.x, centre.x + reach[0]), std::max(hi.y, centre.y + reach[1]),
              std::max(hi.z, centre.z + reach[2])};
#endif
    }
#if defined(__SSE2__)
    float lowOut[4], highOut[4];
    _mm_storeu_ps(lowOut, low);
    _mm_storeu_ps(highOut, high);
    lo = {lowOut[0], lowOut[1], lowOut[2]};
    hi = {highOut[0], highOut[1], highOut[2]};
#endif
    skin.boundsValid = lo.x <= hi.x;
    if (skin.boundsValid) {
        skin.boundsMin = lo;
        skin.boundsMax = hi;
    }
}

}  // namespace candela::content
