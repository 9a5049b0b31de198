// The standard flags every game gets from ApplicationOptions::fromCommandLine: each flag lands
// in its option, a game's own arguments are kept or refused, and bad values name the flag.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "candela/content/render_setting_table.h"
#include "candela/runtime/application_options.h"
#include "candela/runtime/exit_code.h"

using namespace candela::runtime;

namespace {

std::string parseError(const std::vector<std::string>& args) {
    CommandLine result = parseCommandLine(args);
    EXPECT_FALSE(result.options.has_value());
    EXPECT_EQ(result.exitCode, kExitBadArguments);
    return result.error;
}

}  // namespace

TEST(ApplicationOptions, StandardFlagsSetTheirOptions) {
    const std::filesystem::path script =
        std::filesystem::temp_directory_path() / "candela_options_test.input";
    std::ofstream(script) << "0 hold D 5\n";
    CommandLine result =
        parseCommandLine({"--headless", "--frames", "42", "--size", "320x200", "--input",
                          script.string(), "--capture", "a.png", "--capture", "b.exr", "--stats",
                          "s.json", "--step", "0.5", "--lights", "brute-force", "--ibl", "mobile"});
    ASSERT_TRUE(result) << result.error;
    const ApplicationOptions& o = *result.options;
    EXPECT_TRUE(o.headless);
    EXPECT_EQ(o.frames, 42u);
    EXPECT_EQ(o.width, 320u);
    EXPECT_EQ(o.height, 200u);
    ASSERT_TRUE(o.inputScript.has_value());
    InputState input;
    o.inputScript->apply(0, input);
    EXPECT_TRUE(input.down(Key::D));
    ASSERT_EQ(o.captures.size(), 2u);
    EXPECT_EQ(o.captures[0].path, "a.png");
    EXPECT_EQ(o.captures[1].frame, FrameCapture::kLastFrame);
    EXPECT_EQ(o.stats, std::filesystem::path("s.json"));
    EXPECT_DOUBLE_EQ(o.fixedStepSeconds, 0.5);
    EXPECT_EQ(o.lightCulling, candela::render::LightCulling::BruteForce);
    EXPECT_EQ(o.ibl, candela::render::IblMode::Mobile);
    EXPECT_TRUE(result.arguments.empty());
    std::filesystem::remove(script);
}

TEST(ApplicationOptions, DefaultsSurviveWhenNoFlagIsGiven) {
    ApplicationOptions defaults;
    defaults.width = 640;
    defaults.title = "Mine";
    CommandLine result = parseCommandLine({}, OtherArguments::Refuse, defaults);
    ASSERT_TRUE(result);
    EXPECT_EQ(result.options->width, 640u);
    EXPECT_EQ(result.options->title, "Mine");
    EXPECT_FALSE(result.options->headless);
}

TEST(ApplicationOptions, AGamesOwnArgumentsAreKeptInOrderOrRefused) {
    CommandLine kept =
        parseCommandLine({"level.json", "--headless", "--state", "out.json"}, OtherArguments::Keep);
    ASSERT_TRUE(kept) << kept.error;
    EXPECT_TRUE(kept.options->headless);
    EXPECT_EQ(kept.arguments, (std::vector<std::string>{"level.json", "--state", "out.json"}));

    EXPECT_EQ(parseError({"--state", "out.json"}), "unknown option '--state'");
    EXPECT_EQ(parseError({"level.json"}), "unexpected argument 'level.json'");
}

TEST(ApplicationOptions, BadValuesNameTheFlagAndTheValue) {
    EXPECT_NE(parseError({"--size", "12"}).find("--size needs WxH"), std::string::npos);
    EXPECT_NE(parseError({"--size", "0x10"}).find("'0x10'"), std::string::npos);
    EXPECT_NE(parseError({"--frames", "0"}).find("--frames needs a positive integer"),
              std::string::npos);
    EXPECT_NE(parseError({"--frames"}).find("--frames"), std::string::npos);
    EXPECT_NE(parseError({"--capture", "x.jpg"}).find(".exr or .png: 'x.jpg'"), std::string::npos);
    EXPECT_NE(parseError({"--lights", "fast"}).find("got 'fast'"), std::string::npos);
    EXPECT_NE(parseError({"--input", "/no/such/replay.input"}).find("/no/such/replay.input"),
              std::string::npos);
}

TEST(ApplicationOptions, ExposureFlags) {
    CommandLine result = parseCommandLine({"--exposure", "auto", "--exposure-compensation", "1.5"});
    ASSERT_TRUE(result) << result.error;
    EXPECT_EQ(result.options->settings.exposure, candela::render::ExposureMode::Auto);
    EXPECT_EQ(result.options->settings.exposureCompensation, 1.5f);
    EXPECT_NE(parseError({"--exposure", "fast"}).find("--exposure needs manual or auto"),
              std::string::npos);
    EXPECT_NE(parseError({"--exposure-compensation", "x"}).find("got 'x'"), std::string::npos);
    // Issue 44: NaN passed the +-16 check (every frame came out NaN); so did infinities.
    for (const char* bad : {"nan", "-nan", "inf", "-inf", "16.5"}) {
        EXPECT_NE(parseError({"--exposure-compensation", bad}).find("from -16 to 16"),
                  std::string::npos)
            << bad;
    }
}

TEST(ApplicationOptions, AntiAliasingAndBloomFlags) {
    CommandLine result = parseCommandLine({"--aa", "fxaa", "--msaa", "4", "--bloom", "0.1"});
    ASSERT_TRUE(result) << result.error;
    EXPECT_EQ(result.options->settings.aa, candela::render::AntiAliasing::Fxaa);
    EXPECT_EQ(result.options->settings.msaaSamples, 4u);
    EXPECT_EQ(result.options->settings.bloomStrength, 0.1f);
    CommandLine none = parseCommandLine({});
    ASSERT_TRUE(none);
    EXPECT_FALSE(none.options->settings.aa.has_value());           // the scene file's, else TAA
    EXPECT_FALSE(none.options->settings.msaaSamples.has_value());  // the scene file's, else 1 (off)
    EXPECT_FALSE(none.options->settings.bloomStrength.has_value());
    CommandLine gbaa = parseCommandLine({"--aa", "gbaa"});
    ASSERT_TRUE(gbaa) << gbaa.error;
    EXPECT_EQ(gbaa.options->settings.aa, candela::render::AntiAliasing::Gbaa);
    EXPECT_NE(parseError({"--aa", "smaa"}).find("--aa needs off, fxaa, taa or gbaa, got 'smaa'"),
              std::string::npos);
    EXPECT_NE(
        parseError({"--msaa", "3"}).find("--msaa needs 1, 2, 4 or 8 samples per pixel, got '3'"),
        std::string::npos);
    EXPECT_NE(parseError({"--bloom", "2"}).find("--bloom needs a fraction"), std::string::npos);
    EXPECT_NE(parseError({"--bloom", "-0.1"}).find("got '-0.1'"), std::string::npos);
}

// Issue 15: --area-lights picks how sphere and tube lights integrate; LTC unless told.
TEST(ApplicationOptions, AreaLightsFlag) {
    CommandLine result = parseCommandLine({"--area-lights", "representative"});
    ASSERT_TRUE(result) << result.error;
    EXPECT_EQ(result.options->settings.areaLights, candela::render::AreaLightMode::Representative);
    CommandLine ltc = parseCommandLine({"--area-lights", "ltc"});
    ASSERT_TRUE(ltc) << ltc.error;
    EXPECT_EQ(ltc.options->settings.areaLights, candela::render::AreaLightMode::Ltc);
    CommandLine none = parseCommandLine({});
    ASSERT_TRUE(none);
    EXPECT_FALSE(none.options->settings.areaLights);  // the quality preset's
    EXPECT_NE(parseError({"--area-lights", "exact"})
                  .find("--area-lights needs representative or ltc, got 'exact'"),
              std::string::npos);
    EXPECT_NE(parseError({"--area-lights"}).find("--area-lights needs"), std::string::npos);
    EXPECT_NE(ApplicationOptions::standardFlagsUsage().find("--area-lights representative|ltc"),
              std::string::npos);
}

// Issue 41: a textured rect's cells per side, a power of two up to 16 (each cell one texel of
// a level of the image's chain).
TEST(ApplicationOptions, AreaTextureCellsFlag) {
    CommandLine result = parseCommandLine({"--area-texture-cells", "4"});
    ASSERT_TRUE(result) << result.error;
    EXPECT_EQ(result.options->settings.areaTextureCells, 4u);
    EXPECT_FALSE(parseCommandLine({}).options->settings.areaTextureCells);  // the quality preset's
    for (const char* bad : {"0", "3", "32", "x"}) {
        EXPECT_NE(parseError({"--area-texture-cells", bad})
                      .find(std::string("--area-texture-cells needs 1, 2, 4, 8 or 16, got '") +
                            bad + "'"),
                  std::string::npos)
            << bad;
    }
}

// Issue 41: the froxel lighting's per-cluster cap of plain lights, 0 (none) to 4096.
TEST(ApplicationOptions, FroxelLightCapFlag) {
    CommandLine result = parseCommandLine({"--froxel-light-cap", "0"});
    ASSERT_TRUE(result) << result.error;
    EXPECT_EQ(result.options->settings.froxelLightCap, 0u);
    EXPECT_FALSE(parseCommandLine({}).options->settings.froxelLightCap);  // the quality preset's
    for (const char* bad : {"-1", "4097", "x"}) {
        EXPECT_NE(parseError({"--froxel-light-cap", bad})
                      .find(std::string("--froxel-light-cap needs a count from 0 (every light) "
                                        "to 4096, got '") +
                            bad + "'"),
                  std::string::npos)
            << bad;
    }
}

TEST(ApplicationOptions, HelpAsksForTheUsageAndSucceeds) {
    CommandLine result = parseCommandLine({"--frames", "3", "--help"});
    EXPECT_FALSE(result);
    EXPECT_TRUE(result.helpRequested);
    EXPECT_EQ(result.exitCode, kExitOk);
    for (const char* flag :
         {"--headless", "--frames", "--size", "--input", "--capture", "--stats"}) {
        EXPECT_NE(ApplicationOptions::standardFlagsUsage().find(flag), std::string::npos) << flag;
    }
}

// Issue 16: --atmosphere gives the scene Earth's atmosphere; --sun-elevation DEG and
// --time-of-day HH:MM place its sun; bad values name the flag and the value.
TEST(ApplicationOptions, AtmosphereFlags) {
    CommandLine result =
        parseCommandLine({"--atmosphere", "--sun-elevation", "12.5", "--time-of-day", "17:45"});
    ASSERT_TRUE(result.options) << result.error;
    EXPECT_TRUE(result.options->atmosphere);
    ASSERT_TRUE(result.options->sunElevationDegrees);
    EXPECT_EQ(*result.options->sunElevationDegrees, 12.5f);
    ASSERT_TRUE(result.options->timeOfDayHours);
    EXPECT_EQ(*result.options->timeOfDayHours, 17.75f);
    EXPECT_FALSE(parseCommandLine({}).options->atmosphere);
    // `--atmosphere off` drops one (the demo's, in tests about something else).
    CommandLine off = parseCommandLine({"--atmosphere", "off", "--frames", "2"});
    ASSERT_TRUE(off.options) << off.error;
    EXPECT_TRUE(off.options->atmosphereOff);
    EXPECT_FALSE(off.options->atmosphere);
    EXPECT_EQ(off.options->frames, 2u);
    EXPECT_FALSE(result.options->atmosphereOff);
    EXPECT_NE(parseError({"--sun-elevation", "91"}).find("'91'"), std::string::npos);
    EXPECT_NE(parseError({"--sun-elevation", "high"}).find("--sun-elevation needs"),
              std::string::npos);
    EXPECT_NE(parseError({"--time-of-day", "25:00"}).find("'25:00'"), std::string::npos);
    EXPECT_NE(parseError({"--time-of-day", "12:60"}).find("HH:MM"), std::string::npos);
    EXPECT_NE(parseError({"--time-of-day", "noon"}).find("--time-of-day needs"), std::string::npos);
    // Issue 44: hours * 60 overflowed an int and the value was taken.
    EXPECT_NE(parseError({"--time-of-day", "35791395:00"}).find("'35791395:00'"),
              std::string::npos);
    EXPECT_NE(parseError({"--time-of-day", "2147483647:59"}).find("HH:MM"), std::string::npos);
    for (const char* flag :
         {"--atmosphere", "--atmosphere off", "--sun-elevation DEG", "--time-of-day HH:MM"})
        EXPECT_NE(ApplicationOptions::standardFlagsUsage().find(flag), std::string::npos) << flag;
}

// Issue 16: --scattering picks the light shafts' method (unset: the application's epipolar);
// the epipolar parameters are checked counts and a positive threshold.
TEST(ApplicationOptions, ScatteringFlags) {
    CommandLine result =
        parseCommandLine({"--scattering", "brute-force", "--scattering-slices", "64",
                          "--scattering-samples", "32", "--scattering-initial-step", "4",
                          "--scattering-threshold", "0.1", "--scattering-density", "200"});
    ASSERT_TRUE(result) << result.error;
    EXPECT_EQ(result.options->settings.scattering, candela::render::ScatteringMode::BruteForce);
    EXPECT_EQ(result.options->settings.scatteringSlices, 64u);
    EXPECT_EQ(result.options->settings.scatteringSamples, 32u);
    EXPECT_EQ(result.options->scatteringSettings.initialStep, 4u);
    EXPECT_EQ(result.options->scatteringSettings.refinementThreshold, 0.1f);
    EXPECT_EQ(result.options->scatteringSettings.densityScale, 200.0f);
    EXPECT_FALSE(parseCommandLine({}).options->settings.scattering);
    EXPECT_NE(parseError({"--scattering", "fast"}).find("got 'fast'"), std::string::npos);
    EXPECT_NE(parseError({"--scattering-samples", "1"}).find("from 2 to 4096"), std::string::npos);
    EXPECT_NE(parseError({"--scattering-slices", "x"}).find("got 'x'"), std::string::npos);
    EXPECT_NE(parseError({"--scattering-threshold", "0"}).find("positive"), std::string::npos);
    EXPECT_NE(parseError({"--scattering-density", "-1"}).find("--scattering-density needs"),
              std::string::npos);
    EXPECT_NE(ApplicationOptions::standardFlagsUsage().find("--scattering off|epipolar"),
              std::string::npos);
    // Issue 44: each flag within its range, 4096 x 4096 took 38 s for a 64x64 frame; their
    // product is bounded (the side not given counts as the presets' largest, 512 or 256).
    EXPECT_NE(parseError({"--scattering-slices", "4096", "--scattering-samples", "4096"})
                  .find("--scattering-slices 4096 x --scattering-samples 4096 = 16777216 "
                        "samples a frame, past the limit of 1048576"),
              std::string::npos);
    EXPECT_NE(parseError({"--scattering-slices", "4097"}).find("to 4096"), std::string::npos);
    EXPECT_NE(parseError({"--scattering-samples", "4096"})
                  .find("--scattering-slices 512 x --scattering-samples 4096"),
              std::string::npos);
    EXPECT_TRUE(parseCommandLine({"--scattering-slices", "4096"}));  // 4096 x 256 = 2^20
    EXPECT_TRUE(parseCommandLine({"--scattering-slices", "4096", "--scattering-samples", "256"}));
    EXPECT_TRUE(parseCommandLine({"--scattering-samples", "2048"}));  // 512 x 2048 = 2^20
}

// Issue 17: --volumetrics picks the method, --fog SIGMA_S[,SIGMA_A[,G]] a uniform medium by
// the Fog component's rules.
TEST(ApplicationOptions, VolumetricsAndFogFlags) {
    CommandLine result = parseCommandLine({"--volumetrics", "reference", "--fog", "0.1,0.02,-0.6"});
    ASSERT_TRUE(result) << result.error;
    EXPECT_EQ(result.options->settings.volumetrics, candela::render::VolumetricsMode::Reference);
    ASSERT_TRUE(result.options->fog);
    EXPECT_EQ(result.options->fog->scattering, 0.1f);
    EXPECT_EQ(result.options->fog->absorption, 0.02f);
    EXPECT_EQ(result.options->fog->anisotropy, -0.6f);
    CommandLine one = parseCommandLine({"--fog", "0.05"});
    ASSERT_TRUE(one) << one.error;
    EXPECT_EQ(one.options->fog->scattering, 0.05f);
    EXPECT_EQ(one.options->fog->absorption, 0.0f);
    EXPECT_EQ(one.options->fog->anisotropy, 0.0f);
    EXPECT_TRUE(one.warnings.empty());
    // Issue 44: a clamp says so, as the scene file's does (it was silent on the command line).
    for (const char* huge : {"1e30", "inf", "0.1,1e30"}) {
        CommandLine clamped = parseCommandLine({"--fog", huge});
        ASSERT_TRUE(clamped) << clamped.error;
        ASSERT_EQ(clamped.warnings.size(), 1u) << huge;
        EXPECT_EQ(clamped.warnings[0].rfind("clamped: --fog ", 0), 0u) << clamped.warnings[0];
        const bool absorption = std::string(huge).find(',') != std::string::npos;
        EXPECT_NE(clamped.warnings[0].find(absorption ? "absorption" : "scattering"),
                  std::string::npos)
            << clamped.warnings[0];
    }
    EXPECT_FALSE(parseCommandLine({}).options->fog);
    EXPECT_FALSE(parseCommandLine({}).options->settings.volumetrics);
    EXPECT_FALSE(parseCommandLine({}).options->settings.volumeProxies);
    EXPECT_EQ(parseCommandLine({"--volume-proxies", "on"}).options->settings.volumeProxies, true);
    EXPECT_EQ(parseCommandLine({"--volume-proxies", "off"}).options->settings.volumeProxies, false);
    EXPECT_NE(parseError({"--volume-proxies", "yes"}).find("--volume-proxies needs off or on"),
              std::string::npos);
    EXPECT_NE(parseError({"--volume-proxies"}).find("--volume-proxies needs"), std::string::npos);

    EXPECT_NE(parseError({"--volumetrics", "fast"}).find("got 'fast'"), std::string::npos);
    EXPECT_NE(parseError({"--fog", "-0.1"}).find("scattering must not be negative"),
              std::string::npos);
    EXPECT_NE(parseError({"--fog", "0.1,0,1"}).find("anisotropy"), std::string::npos);
    EXPECT_NE(parseError({"--fog", "0.1,x"}).find("'0.1,x'"), std::string::npos);
    EXPECT_NE(parseError({"--fog", "0.1,0,0,4"}).find("at most three"), std::string::npos);
    EXPECT_NE(parseError({"--fog"}).find("--fog needs"), std::string::npos);
}

// --light-assign chooses where lights are assigned to clusters (Cli tests show cpu and gpu
// give the same image); a bad value names the flag and the choices.
TEST(ApplicationOptions, LightAssignFlagChoosesTheDevice) {
    using candela::render::LightAssignmentDevice;
    for (auto [name, device] : {std::pair{"auto", LightAssignmentDevice::Auto},
                                std::pair{"cpu", LightAssignmentDevice::Cpu},
                                std::pair{"gpu", LightAssignmentDevice::Gpu}}) {
        CommandLine result = parseCommandLine({"--light-assign", name});
        ASSERT_TRUE(result) << result.error;
        EXPECT_EQ(result.options->lightAssignment, device) << name;
    }
    EXPECT_EQ(parseCommandLine({}).options->lightAssignment, LightAssignmentDevice::Auto);
    EXPECT_NE(parseError({"--light-assign", "tpu"}).find("--light-assign needs auto, cpu or gpu"),
              std::string::npos);
}

// Issue 41: --quality names a preset; anything else is refused with the choices.
TEST(ApplicationOptions, QualityFlag) {
    CommandLine low = parseCommandLine({"--quality", "low"});
    ASSERT_TRUE(low) << low.error;
    EXPECT_EQ(low.options->quality, candela::content::QualityLevel::Low);
    CommandLine none = parseCommandLine({});
    ASSERT_TRUE(none);
    EXPECT_FALSE(none.options->quality);  // the scene's, else the device's
    EXPECT_NE(parseError({"--quality", "epic"})
                  .find("--quality needs low, medium, high or ultra, got 'epic'"),
              std::string::npos);
    EXPECT_NE(ApplicationOptions::standardFlagsUsage().find("--quality low|medium|high|ultra"),
              std::string::npos);
}

// Every row of the render settings table is a flag: each value the row names (or its least
// and its ultra value) reaches ApplicationOptions::settings, a value it does not take is refused
// naming the flag, and the usage lists the flag with its values.
TEST(ApplicationOptions, EveryRenderSettingIsAFlag) {
    candela::content::forEachRenderSetting([&](const auto& row) {
        const std::string flag(row.flag);
        SCOPED_TRACE(flag);
        using T = std::decay_t<decltype(row.presets[0])>;
        std::vector<T> values;
        for (const auto& named : row.names)
            values.push_back(named.value);
        if (row.names.empty()) values = {row.least, row.presets[3]};
        for (const T value : values) {
            const std::string text = candela::content::renderSettingText(row, value);
            const CommandLine result = parseCommandLine({flag, text});
            ASSERT_TRUE(result.options) << result.error;
            EXPECT_EQ(result.options->settings.*row.choice, value) << text;
        }
        EXPECT_NE(parseError({flag, "sideways"}).find(flag + " needs "), std::string::npos);
        EXPECT_NE(parseError({flag}).find(flag + " needs "), std::string::npos);
        EXPECT_FALSE((parseCommandLine({}).options->settings.*row.choice).has_value());
        EXPECT_NE(ApplicationOptions::standardFlagsUsage().find(
                      "  " + flag + " " + candela::content::renderSettingNames(row, "|")),
                  std::string::npos);
    });
}
