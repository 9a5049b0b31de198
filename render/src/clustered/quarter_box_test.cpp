#include "clustered/quarter_box_test.h"

#include <bit>

#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

namespace candela::render {

uint32_t quarterBoxesTouched(const LightBounds& b, const float* boxes, float padPerDepth) {
#if defined(__SSE2__)
    // Four boxes of six floats (q0 = a0..a5, q1 = b0..b5, ...) into one register per bound and
    // axis, lane q for quarter q.
    const __m128 v0 = _mm_loadu_ps(boxes), v1 = _mm_loadu_ps(boxes + 4);
    const __m128 v2 = _mm_loadu_ps(boxes + 8), v3 = _mm_loadu_ps(boxes + 12);
    const __m128 v4 = _mm_loadu_ps(boxes + 16), v5 = _mm_loadu_ps(boxes + 20);
    __m128 q0 = v0;                                               // a0 a1 a2 a3
    __m128 q1 = _mm_shuffle_ps(v1, v2, _MM_SHUFFLE(1, 0, 3, 2));  // b0 b1 b2 b3
    __m128 q2 = v3;                                               // c0 c1 c2 c3
    __m128 q3 = _mm_shuffle_ps(v4, v5, _MM_SHUFFLE(1, 0, 3, 2));  // d0 d1 d2 d3
    _MM_TRANSPOSE4_PS(q0, q1, q2, q3);
    const __m128 loX = q0, loY = q1, loZ = q2, hiX = q3;
    const __m128 ab = _mm_shuffle_ps(v1, v2, _MM_SHUFFLE(3, 2, 1, 0));  // a4 a5 b4 b5
    const __m128 cd = _mm_shuffle_ps(v4, v5, _MM_SHUFFLE(3, 2, 1, 0));  // c4 c5 d4 d5
    const __m128 hiY = _mm_shuffle_ps(ab, cd, _MM_SHUFFLE(2, 0, 2, 0));
    const __m128 hiZ = _mm_shuffle_ps(ab, cd, _MM_SHUFFLE(3, 1, 3, 1));
    // As boundingShapeTouchesBoxes skips a box: min x > max x means no pixel.
    const uint32_t occupied = uint32_t(_mm_movemask_ps(_mm_cmpngt_ps(loX, hiX)));
    // Capsules test their bounding sphere per quarter but their capsule per cluster.
    if (b.shape != LightShape::Capsule && std::has_single_bit(occupied)) return occupied;

    // distanceSqPointBox on the padded boxes. glm::max(x, y) is (x < y) ? y : x, which
    // _mm_max_ps(y, x) is exactly (signed zeros and NaN included); glm::dot sums x, y, then z.
    const __m128 zero = _mm_setzero_ps();
    const __m128 pad = _mm_mul_ps(_mm_set1_ps(padPerDepth), _mm_sub_ps(_mm_set1_ps(1.0f), loZ));
    auto axisSquare = [&](__m128 lo, __m128 hi, float centre) {
        const __m128 p = _mm_set1_ps(centre);
        lo = _mm_sub_ps(lo, pad);
        hi = _mm_add_ps(hi, pad);
        const __m128 d = _mm_max_ps(zero, _mm_max_ps(_mm_sub_ps(p, hi), _mm_sub_ps(lo, p)));
        return _mm_mul_ps(d, d);
    };
    const __m128 distanceSq =
        _mm_add_ps(_mm_add_ps(axisSquare(loX, hiX, b.center.x), axisSquare(loY, hiY, b.center.y)),
                   axisSquare(loZ, hiZ, b.center.z));
    const float r = paddedBoundingRadius(b);
    uint32_t touched =
        uint32_t(_mm_movemask_ps(_mm_cmple_ps(distanceSq, _mm_set1_ps(r * r)))) & occupied;
    if (b.shape != LightShape::Cone) return touched;
    // Cones: the quarters inside the bounding sphere still take the cone test, as
    // boundingShapeTouchesBoxes gives them (lightTouchesBox repeats the sphere test first).
    for (uint32_t bits = touched; bits; bits &= bits - 1) {
        const uint32_t q = uint32_t(std::countr_zero(bits));
        const float* box = boxes + 6 * q;
        const glm::vec3 lo(box[0], box[1], box[2]), hi(box[3], box[4], box[5]);
        const glm::vec3 padding(padPerDepth * (1.0f - lo.z));
        if (!lightTouchesBox(b, lo - padding, hi + padding)) touched &= ~(1u << q);
    }
    return touched;
#else
    return boundingShapeTouchesBoxes(b, boxes, 4, padPerDepth);
#endif
}

}  // namespace candela::render
