// The binary16 emulation the fp16 report rests on: exact values, rounding to nearest even,
// subnormals, overflow, and (where the compiler has _Float16) agreement with the compiler's
// own conversion over millions of floats.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "half_float.h"

using namespace candela::stability;

TEST(HalfFloat, KeepsExactHalves) {
    for (float v : {0.0f, 1.0f, -2.0f, 0.5f, 65504.0f, kHalfMinNormal, kHalfMinSubnormal,
                    1.0f + kHalfEpsilon, 3.0f * kHalfMinSubnormal}) {
        EXPECT_EQ(roundToHalf(v), v) << v;
    }
    EXPECT_TRUE(std::signbit(roundToHalf(-0.0f)));
    EXPECT_TRUE(std::isnan(roundToHalf(std::numeric_limits<float>::quiet_NaN())));
}

TEST(HalfFloat, RoundsToNearestEven) {
    EXPECT_EQ(roundToHalf(1.0f + kHalfEpsilon / 2), 1.0f);  // tie -> even (1.0)
    EXPECT_EQ(roundToHalf(1.0f + 3 * kHalfEpsilon / 2), 1.0f + 2 * kHalfEpsilon);  // tie -> even
    EXPECT_EQ(roundToHalf(1.0f + 0.6f * kHalfEpsilon), 1.0f + kHalfEpsilon);
    EXPECT_EQ(roundToHalf(0.1f), 0.0999755859375f);
    EXPECT_EQ(roundToHalf(kHalfMinSubnormal / 2), 0.0f);                       // tie -> 0
    EXPECT_EQ(roundToHalf(3 * kHalfMinSubnormal / 2), 2 * kHalfMinSubnormal);  // tie -> even
    EXPECT_EQ(roundToHalf(0.6f * kHalfMinSubnormal), kHalfMinSubnormal);
}

TEST(HalfFloat, OverflowsToInfinityFromTheMidpointAbove65504) {
    EXPECT_EQ(roundToHalf(65519.0f), 65504.0f);
    EXPECT_EQ(roundToHalf(65520.0f), std::numeric_limits<float>::infinity());
    EXPECT_EQ(roundToHalf(-1e6f), -std::numeric_limits<float>::infinity());
}

TEST(HalfFloat, ArithmeticRoundsEveryResult) {
    EXPECT_EQ(float(Half(1.0f) + Half(kHalfEpsilon / 4)), 1.0f);
    EXPECT_EQ(float(Half(65504.0f) * Half(2.0f)), std::numeric_limits<float>::infinity());
    EXPECT_EQ(float(Half(kHalfMinSubnormal) / Half(4.0f)), 0.0f);
    EXPECT_EQ(float(Half(1.0f) - Half(0.99999f)), 0.0f);  // 0.99999 is 1 in half
    EXPECT_EQ(float(exp2(Half(-12.54f))), roundToHalf(std::exp2(roundToHalf(-12.54f))));
}

#if defined(__FLT16_MAX__)
// Independent check against the compiler's float -> _Float16 conversion (IEEE round to
// nearest even): every 997th float bit pattern, positive and negative, all exponents.
TEST(HalfFloat, AgreesWithCompilerFloat16Conversion) {
    uint64_t compared = 0;
    for (uint64_t bits = 0; bits < 0x100000000ull; bits += 997) {
        const float x = std::bit_cast<float>(uint32_t(bits));
        if (std::isnan(x)) continue;
        const float expected = float(static_cast<_Float16>(x));
        ASSERT_EQ(std::bit_cast<uint32_t>(roundToHalf(x)), std::bit_cast<uint32_t>(expected))
            << "x = " << x;
        ++compared;
    }
    EXPECT_GT(compared, 4000000u);
}
#endif
