// The render settings table (content/render_setting_table.h) drives the command line, the scene
// reader and writer, the editor and --stats: every row must be well formed, survive a scene
// file under its own key and have its bad values named there.
#include <gtest/gtest.h>

#include <set>
#include <span>
#include <string>
#include <type_traits>

#include "candela/content/render_setting_table.h"
#include "candela/content/scene_file.h"

namespace candela::content {
namespace {

// A value the row allows other than its ultra preset (so writing it is a real choice).
template <typename T>
T otherValue(const RenderSettingRow<T>& row) {
    if (!row.names.empty()) {
        for (const NamedValue<T>& named : row.names) {
            if (named.value != row.presets[3]) return named.value;
        }
    }
    if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) {
        return row.presets[3] == row.most ? row.least : row.most;
    }
    return row.presets[3];
}

TEST(RenderSettingTable, RowsAreWellFormed) {
    std::set<std::string_view> flags, keys, stats;
    std::set<const void*> members;
    forEachRenderSetting([&](const auto& row) {
        SCOPED_TRACE(std::string(row.flag));
        EXPECT_TRUE(row.flag.starts_with("--"));
        EXPECT_TRUE(flags.insert(row.flag).second) << "flag twice";
        EXPECT_TRUE(keys.insert(row.sceneKey).second) << "scene key twice";
        EXPECT_TRUE(stats.insert(row.statsName).second) << "stats name twice";
        EXPECT_FALSE(row.help.empty());
        const RenderSettings defaults;
        EXPECT_TRUE(members.insert(&(defaults.*row.value)).second) << "member twice";
        // Every preset's value is one the row allows, and its spelling reads back as itself.
        for (const auto& value : row.presets) {
            EXPECT_TRUE(renderSettingAllows(row, value));
            EXPECT_EQ(parseRenderSetting(row, renderSettingText(row, value)), value);
        }
        // The renderer's plain default is allowed too.
        EXPECT_TRUE(renderSettingAllows(row, defaults.*row.value));
        EXPECT_FALSE(parseRenderSetting(row, "not-a-value").has_value());
        EXPECT_FALSE(renderSettingExpects(row).empty());
    });
    EXPECT_EQ(flags.size(), std::tuple_size_v<decltype(kRenderSettingTable)>);
}

TEST(RenderSettingTable, PresetsResolveUnderChoicesInOrder) {
    RenderSettingChoices flag, scene;
    scene.ssr = SsrMode::Reference;
    scene.bloomStrength = 0.5f;
    flag.bloomStrength = 0.25f;
    const RenderSettings low = resolveRenderSettings(QualityLevel::Low, {&flag, &scene});
    EXPECT_EQ(low.ssr, SsrMode::Reference);  // the scene's, over the preset's off
    EXPECT_EQ(low.bloomStrength, 0.25f);     // the flag's, over the scene's
    const RenderSettings plain = resolveRenderSettings(QualityLevel::Ultra, {nullptr});
    forEachRenderSetting([&](const auto& row) {
        EXPECT_EQ(plain.*row.value, row.presets[3]) << row.flag;
        EXPECT_EQ(low.*row.value == row.presets[0], !(flag.*row.choice) && !(scene.*row.choice))
            << row.flag;
    });
}

TEST(RenderSettingTable, EveryRowRoundTripsThroughASceneFileUnderItsKey) {
    SceneDocument scene;
    forEachRenderSetting([&](const auto& row) { scene.settings.*row.choice = otherValue(row); });
    std::string error;
    const std::string text = sceneToJson(scene, error);
    ASSERT_EQ(error, "");
    forEachRenderSetting([&](const auto& row) {
        const std::string key(sceneKeyPath(row.sceneKey).member);
        EXPECT_NE(text.find("\"" + key + "\""), std::string::npos) << row.sceneKey << "\n" << text;
    });
    Diagnostics diagnostics;
    auto loaded = parseSceneJson(std::as_bytes(std::span(text)), "all.scene.json", diagnostics);
    ASSERT_TRUE(loaded) << diagnostics.toString();
    EXPECT_TRUE(diagnostics.messages.empty()) << diagnostics.toString();
    EXPECT_EQ(loaded->settings, scene.settings);
}

TEST(RenderSettingTable, EveryRowNamesItsBadValueAndLoadsWithoutIt) {
    forEachRenderSetting([&](const auto& row) {
        SCOPED_TRACE(std::string(row.sceneKey));
        // A name no row has, or a number past the row's range.
        std::string value = "\"sideways\"";
        if (row.names.empty()) value = std::to_string(double(row.most) * 4 + 3);
        const SceneKeyPath path = sceneKeyPath(row.sceneKey);
        const std::string key(row.sceneKey), member(path.member);
        std::string json = "{\"" + member + "\": " + value + ", ";
        if (!path.object.empty()) {
            json = "{\"" + std::string(path.object) + "\": {\"" + member + "\": " + value + "}, ";
        }
        json += R"("format": "candela.scene", "version": 1, "entities": []})";
        Diagnostics diagnostics;
        auto loaded = parseSceneJson(std::as_bytes(std::span(json)), "bad.scene.json", diagnostics);
        ASSERT_TRUE(loaded) << diagnostics.toString();
        EXPECT_FALSE((loaded->settings.*row.choice).has_value());
        EXPECT_TRUE(diagnostics.mentions("bad.scene.json: /" + key + ": error: ") &&
                    diagnostics.mentions(renderSettingExpects(row)))
            << diagnostics.toString();
    });
}

}  // namespace
}  // namespace candela::content
