// Where a source is heard: inverse-distance attenuation, the stereo panning law and Doppler,
// measured on the loopback mix.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "audio_test_support.h"

namespace candela::audio::test {
namespace {

content::AudioSource loopedTone() {
    content::AudioSource source;
    source.clip = writeClip("tone_1khz.wav", sine(0.1, 1000.0, 0.5f, kRate)).string();
    source.loop = true;
    return source;
}

// RMS of both channels together, after the first step (a source starts at full gain, but
// leave OpenAL's first parameter ramp out of it).
double loudness(const Channels& c) {
    return std::hypot(rms(c.left, 1600), rms(c.right, 1600));
}

double loudnessAt(const content::AudioSource& source, ecs::Vec3 position) {
    LoopbackMix mix;
    mix.addListener({0, 0, 0});
    mix.addSource(source, position);
    return loudness(mix.run(10));
}

TEST(SpatialMix, DistanceGainFollowsTheInverseDistanceModelWithinOnePercent) {
    content::AudioSource source = loopedTone();
    // minDistance 1, rolloff 1: gain 1 / d, so 4 m is a quarter of 1 m.
    const double near = loudnessAt(source, {0, 0, -1});
    const double far = loudnessAt(source, {0, 0, -4});
    ASSERT_GT(far, 0.0);
    EXPECT_NEAR(near / far, 4.0, 0.04);
    // minDistance 2, rolloff 0.5: full gain up to 2 m, then 2 / (2 + 0.5 (d - 2)).
    source.minDistance = 2.0f;
    source.rolloff = 0.5f;
    const double inside = loudnessAt(source, {0, 0, -1});
    const double outside = loudnessAt(source, {0, 0, -4});
    EXPECT_NEAR(inside / outside, 1.5, 0.015);
    // Past maxDistance the gain stops falling.
    source.maxDistance = 3.0f;
    EXPECT_NEAR(loudnessAt(source, {0, 0, -3}) / loudnessAt(source, {0, 0, -30}), 1.0, 0.01);
}

// OpenAL Soft 1.19's stereo pan: the direction encoded to first-order ambisonics (N3D) and
// decoded to two speakers, the front azimuth widened 1.5x first (a source past 60 degrees is
// fully in one channel). Left and right gains for a source `degrees` to the left.
std::pair<double, double> panGains(double degrees) {
    const double widened = std::min(1.5 * degrees, 90.0) * std::numbers::pi / 180.0;
    const double side = 0.5 * std::sin(widened);
    const double front = 0.0552305643 * std::sqrt(3.0) * std::cos(widened);
    return {std::clamp(0.5 + side + front, 0.0, 1.0), std::clamp(0.5 - side + front, 0.0, 1.0)};
}

Channels mixFrom(double degreesLeft) {
    LoopbackMix mix;
    mix.addListener({0, 0, 0});
    const double a = degreesLeft * std::numbers::pi / 180.0;
    mix.addSource(loopedTone(), {float(-2 * std::sin(a)), 0, float(-2 * std::cos(a))});
    return mix.run(10);
}

TEST(SpatialMix, ASourceToTheLeftIsLouderInTheLeftChannelByThePanningLaw) {
    const Channels left90 = mixFrom(90.0);
    EXPECT_GT(rms(left90.left, 1600), 0.05);
    EXPECT_LT(rms(left90.right, 1600), 1e-4 * rms(left90.left, 1600));
    for (double degrees : {15.0, 30.0}) {
        SCOPED_TRACE(degrees);
        const Channels c = mixFrom(degrees);
        const auto [l, r] = panGains(degrees);
        EXPECT_NEAR(rms(c.left, 1600) / rms(c.right, 1600), l / r, 0.01 * l / r);
    }
    // Straight ahead both channels are equal; to the right, the mirror image.
    const Channels ahead = mixFrom(0.0);
    EXPECT_NEAR(rms(ahead.left, 1600), rms(ahead.right, 1600), 1e-6);
    const Channels right30 = mixFrom(-30.0);
    const auto [l, r] = panGains(30.0);
    EXPECT_NEAR(rms(right30.right, 1600) / rms(right30.left, 1600), l / r, 0.01 * l / r);
}

TEST(SpatialMix, AnApproachingSourceIsHigherByTheDopplerRatio) {
    LoopbackMix mix;
    mix.addListener({0, 0, 0});
    const ecs::Entity e = mix.addSource(loopedTone(), {0, 0, -30});
    // A tenth of the speed of sound towards the listener: f c / (c - v) = 1111 Hz.
    const float speed = 34.33f;
    Channels all;
    for (int step = 0; step < 12; ++step) {
        mix.move(e, {0, 0, -30 + speed * float(step) * 1600.0f / kRate});
        const Channels c = mix.run(1);
        all.left.insert(all.left.end(), c.left.begin(), c.left.end());
    }
    // Zero crossings over the last ten steps (the first has no velocity yet).
    int crossings = 0;
    for (std::size_t i = 2 * 1600 + 1; i < all.left.size(); ++i)
        crossings += (all.left[i - 1] < 0) != (all.left[i] < 0);
    const double seconds = 10.0 * 1600.0 / kRate;
    const double heard = crossings / (2.0 * seconds);
    EXPECT_NEAR(heard, 1000.0 * 343.3 / (343.3 - speed), 11.0);
}

TEST(SpatialMix, ANonSpatialSourceIgnoresWhereItIs) {
    content::AudioSource source = loopedTone();
    source.spatial = false;
    const double near = loudnessAt(source, {-1, 0, 0});
    const double far = loudnessAt(source, {40, 0, 0});
    EXPECT_NEAR(near / far, 1.0, 1e-6);
    LoopbackMix mix;
    mix.addListener({0, 0, 0});
    mix.addSource(source, {-1, 0, 0});  // to the left, yet centred
    const Channels c = mix.run(4);
    EXPECT_NEAR(rms(c.left, 1600), rms(c.right, 1600), 1e-6);
}

TEST(SpatialMix, WithoutAListenerTheCameraListens) {
    LoopbackMix mix;
    const ecs::Entity camera = mix.registry.create();
    mix.registry.emplace<content::Camera>(camera);
    mix.registry.emplace<ecs::WorldTransform>(camera);
    mix.move(camera, {10, 0, 0});
    mix.addSource(loopedTone(), {9, 0, 0});  // a metre to the camera's left
    const Channels c = mix.run(10);
    EXPECT_GT(rms(c.left, 1600), 0.1);
    EXPECT_LT(rms(c.right, 1600), 1e-4);
}

}  // namespace
}  // namespace candela::audio::test
