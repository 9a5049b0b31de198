// The hierarchy and inspector panels driven by simulated mouse input on a headless ImGui
// context (no window, no GPU): click to select, drag-and-drop to reparent, a drag on the lumens
// field edits the light live as one undo step.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "app/hierarchy_panel.h"
#include "app/inspector_panel.h"
#include "candela/content/asset_cache.h"
#include "candela/content/component_validation.h"
#include "candela/content/components/animation.h"
#include "candela/content/components/light.h"
#include "candela/content/light_texture.h"
#include "candela/content/model.h"
#include "candela/content/png_writer.h"
#include "candela/content/render_setting_table.h"
#include "candela/content/scene_instantiation.h"
#include "candela/ecs/hierarchy.h"
#include "candela/ui/imgui_layer.h"
#include "model/editor_scene.h"

namespace candela::editor {
namespace {

class EditorPanels : public ::testing::Test {
protected:
    void SetUp() override {
        content::SceneDocument doc;
        for (const char* name : {"floor", "lamp", "camera"})
            doc.entities.emplace_back().name = name;
        doc.entities[1].light = content::Light{};
        doc.entities[1].light->lumens = 8000.0f;
        content::Diagnostics diagnostics;
        content::instantiateScene(registry, doc, "panels.scene.json", cache, diagnostics);
        scene = std::make_unique<EditorScene>(registry, "panels.scene.json");
        // Headless ImGui needs its font atlas built before the first frame.
        unsigned char* pixels = nullptr;
        int w = 0, h = 0;
        ImGui::GetIO().Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
        inspector.layout = &inspectorLayout;
        frame(ImVec2(-1, -1), false);  // lay out once with the mouse outside
    }

    // One frame with the mouse at `mouse`, the left button `down`.
    void frame(ImVec2 mouse, bool down) {
        ImGuiIO& io = ImGui::GetIO();
        io.MousePos = mouse;
        io.MouseDown[0] = down;
        layer.beginFrame(800.0f, 600.0f, 1.0f / 60.0f);
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(ImVec2(300, 600));
        ImGui::Begin("Hierarchy");
        drawHierarchyPanel(*scene, &rows);
        ImGui::End();
        ImGui::SetNextWindowPos(ImVec2(300, 0));
        ImGui::SetNextWindowSize(ImVec2(500, 600));
        ImGui::Begin("Inspector");
        drawInspectorPanel(*scene, inspector);
        ImGui::End();
        layer.endFrame();
    }
    // Press at `from`, move to `to` over several frames, release there.
    void drag(ImVec2 from, ImVec2 to) {
        frame(from, false);
        frame(from, true);
        for (int i = 1; i <= 6; ++i) {
            const float t = float(i) / 6.0f;
            frame(ImVec2(from.x + (to.x - from.x) * t, from.y + (to.y - from.y) * t), true);
        }
        frame(to, false);
        frame(to, false);
    }
    ImVec2 row(const std::string& name) {
        return rows.at(scene->idOf(scene->findByName(name))).center();
    }
    // Opens a combo's list and clicks its row `index` (0: the first).
    void chooseFromList(InspectorWidget combo, int index) {  // a copy: frames redo the layout
        frame(combo.center(), true);
        frame(combo.center(), false);
        frame(ImVec2(-1, -1), false);  // the list is open below the field
        // Its rows: one text line and the item spacing each, after the popup's padding.
        const ImGuiStyle& style = ImGui::GetStyle();
        const float rowHeight = ImGui::GetTextLineHeight() + style.ItemSpacing.y;
        const ImVec2 at(combo.center().x, combo.max.y + style.WindowPadding.y +
                                              (float(index) + 0.5f) * rowHeight -
                                              0.5f * style.ItemSpacing.y);
        frame(at, true);
        frame(at, false);
        frame(ImVec2(-1, -1), false);
    }
    // Clicks the entity's row; after the frame that follows, the inspector shows it.
    void select(const std::string& name) {
        frame(row(name), true);
        frame(row(name), false);
        frame(ImVec2(-1, -1), false);
    }

    ecs::Registry registry;
    content::AssetCache cache;
    std::unique_ptr<EditorScene> scene;
    ui::ImGuiLayer layer;
    HierarchyLayout rows;
    InspectorState inspector;
    InspectorLayout inspectorLayout;
};

TEST_F(EditorPanels, ClickSelectsAndDragOntoAnotherRowReparents) {
    ASSERT_EQ(rows.size(), 3u);
    frame(row("camera"), true);
    frame(row("camera"), false);
    EXPECT_EQ(scene->selected(), scene->findByName("camera"));

    drag(row("camera"), row("floor"));
    EXPECT_EQ(ecs::parentOf(registry, scene->findByName("camera")), scene->findByName("floor"));
    EXPECT_EQ(scene->commands().undoLabel(), "Reparent");
    EXPECT_EQ(scene->commands().undoCount(), 1u);
    // Dropping a parent onto its own child is refused.
    frame(ImVec2(-1, -1), false);
    drag(row("floor"), row("camera"));
    EXPECT_EQ(ecs::parentOf(registry, scene->findByName("floor")), ecs::kNullEntity);
    EXPECT_EQ(scene->commands().undoCount(), 1u);
    ASSERT_TRUE(scene->undo());
    EXPECT_EQ(ecs::parentOf(registry, scene->findByName("camera")), ecs::kNullEntity);
}

// Issue 41: with nothing selected the inspector shows the scene's quality preset; choosing one
// in its list sets the scene's "quality" and marks the scene modified.
TEST_F(EditorPanels, TheQualityPresetIsChosenFromTheScenesSettings) {
    ASSERT_EQ(scene->selected(), ecs::kNullEntity);
    ASSERT_TRUE(inspectorLayout.count("Quality preset"));
    EXPECT_FALSE(scene->sceneQuality().has_value());
    chooseFromList(inspectorLayout.at("Quality preset"), 4);  // device's, low ... ultra
    EXPECT_EQ(scene->sceneQuality(), content::QualityLevel::Ultra);
    EXPECT_TRUE(scene->modified());
}

// Every render setting has its widget under its stats name; choosing "gbaa" in the "aa" list
// sets the scene file's "aa" and marks the scene modified; the others stay the preset's.
TEST_F(EditorPanels, RenderSettingsAreChosenFromTheScenesSettings) {
    ASSERT_EQ(scene->selected(), ecs::kNullEntity);
    content::forEachRenderSetting([&](const auto& row) {
        EXPECT_TRUE(inspectorLayout.count(std::string(row.statsName))) << row.statsName;
    });
    chooseFromList(inspectorLayout.at("aa"), 4);  // preset's, off, fxaa, taa, gbaa
    content::RenderSettingChoices expected;
    expected.aa = content::AntiAliasing::Gbaa;
    EXPECT_EQ(scene->sceneRenderSettings(), expected);
    EXPECT_TRUE(scene->modified());
}

TEST_F(EditorPanels, DraggingTheLumensFieldIsOneLiveUndoStep) {
    select("lamp");  // the inspector now shows the lamp
    ASSERT_TRUE(inspectorLayout.count("Set Lumens"));
    const ImVec2 field = inspectorLayout.at("Set Lumens").center();
    const ecs::Entity lamp = scene->findByName("lamp");
    const ecs::Tick before = registry.currentTick();
    registry.advanceTick();
    drag(field, ImVec2(field.x + 60.0f, field.y));
    const float lumens = registry.get<content::Light>(lamp).lumens;
    EXPECT_GT(lumens, 8000.0f + 100.0f);                               // 10 lm per pixel of drag
    EXPECT_TRUE(registry.changedSince<content::Light>(lamp, before));  // what the renderer sees
    EXPECT_EQ(scene->commands().undoCount(), 1u) << "a drag is one undo step";
    EXPECT_EQ(scene->commands().undoLabel(), "Set Lumens");
    ASSERT_TRUE(scene->undo());
    EXPECT_EQ(registry.get<content::Light>(lamp).lumens, 8000.0f);
}

// Issue 22: a value typed into a field (Ctrl+click) went past the widget's range, and the
// editor saved lumens -1, which the loader then dropped with the light. The inspector applies
// the loader's rules: -1 is refused (no edit, a notice), 3e38 is clamped to the limit.
TEST_F(EditorPanels, TypedValuesTheLoaderWouldRejectAreRefusedAndAbsurdOnesClamped) {
    select("lamp");  // the inspector now shows the lamp
    ASSERT_TRUE(inspectorLayout.count("Set Lumens"));
    const ImVec2 field = inspectorLayout.at("Set Lumens").center();
    const ecs::Entity lamp = scene->findByName("lamp");
    auto type = [&](const char* text) {
        ImGuiIO& io = ImGui::GetIO();
        io.KeyCtrl = true;  // Ctrl+click turns the drag field into a text field
        frame(field, true);
        frame(field, false);
        io.KeyCtrl = false;
        for (const char* c = text; *c; ++c) {  // one character per frame, as typed
            io.AddInputCharacter(static_cast<unsigned>(*c));
            frame(field, false);
        }
        frame(ImVec2(-1, -1), true);  // click elsewhere: the field closes
        frame(ImVec2(-1, -1), false);
    };
    type("-1");
    EXPECT_EQ(registry.get<content::Light>(lamp).lumens, 8000.0f);
    EXPECT_EQ(scene->commands().undoCount(), 0u);

    type("3e38");
    EXPECT_EQ(registry.get<content::Light>(lamp).lumens, content::kMaxLumens);
    EXPECT_GE(scene->commands().undoCount(), 1u);
}

// Issue 15: a rect light's emissive image from the inspector's Texture field: an unreadable
// file is refused with a notice (no edit); a readable one is decoded and set as one undo step.
TEST_F(EditorPanels, RectLightTextureFieldSetsTheImageAndRefusesUnreadableFiles) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / "candela_editor_light_texture";
    std::filesystem::create_directories(dir);
    const std::string png = (dir / "screen.png").string();
    const std::uint8_t pixels[2 * 2 * 3] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
    ASSERT_EQ(content::writePng(png, 2, 2, 3, pixels), "");
    const ecs::Entity lamp = scene->findByName("lamp");
    registry.get<content::Light>(lamp).type = content::LightType::Rect;
    select("lamp");  // the inspector now shows the rect
    ASSERT_TRUE(inspectorLayout.count("Set Light Texture"));
    const ImVec2 field = inspectorLayout.at("Set Light Texture").center();
    ImGuiIO& io = ImGui::GetIO();
    constexpr int kEnter = 13;
    io.KeyMap[ImGuiKey_Enter] = kEnter;
    auto enter = [&](const std::string& text) {
        frame(field, true);
        frame(field, false);
        for (char c : text) {  // one character per frame, as typed
            io.AddInputCharacter(static_cast<unsigned>(c));
            frame(field, false);
        }
        io.KeysDown[kEnter] = true;
        frame(field, false);
        io.KeysDown[kEnter] = false;
        frame(ImVec2(-1, -1), false);
    };
    enter((dir / "missing.png").string());
    EXPECT_EQ(registry.get<content::Light>(lamp).texture, 0u);
    EXPECT_EQ(scene->commands().undoCount(), 0u);

    enter(png);
    const auto texture = content::findLightTexture(registry.get<content::Light>(lamp).texture);
    ASSERT_TRUE(texture);
    ASSERT_TRUE(texture->image);
    EXPECT_EQ(texture->file, png);
    EXPECT_EQ(scene->commands().undoLabel(), "Set Light Texture");
    std::filesystem::remove_all(dir);
}

// Issue 20: the inspector's Animation section on an entity with a player: the button pauses
// and resumes, the time slider scrubs (and pauses), and the clip list names the model's clips.
TEST_F(EditorPanels, AnimationSectionPausesAndScrubsThePlayer) {
    content::Model model;
    model.animations.resize(2);
    model.animations[0].name = "Wave";
    model.animations[0].duration = 2.0f;
    model.animations[1].name = "Spin";
    model.animations[1].duration = 1.0f;
    const ecs::Entity floor = scene->findByName("floor");
    content::AnimationPlayer& player = registry.emplace<content::AnimationPlayer>(floor);
    player.model = &model;
    player.play(0);
    select("floor");  // the inspector now shows the floor
    ASSERT_TRUE(inspectorLayout.count("Animation play"));
    ASSERT_TRUE(inspectorLayout.count("Animation time"));
    ASSERT_TRUE(inspectorLayout.count("Animation clip"));
    const ImVec2 button = inspectorLayout.at("Animation play").center();
    frame(button, true);
    frame(button, false);
    EXPECT_FALSE(registry.get<content::AnimationPlayer>(floor).playing);
    frame(button, true);
    frame(button, false);
    EXPECT_TRUE(registry.get<content::AnimationPlayer>(floor).playing);
    // A drag along the slider from its left end scrubs into the clip and pauses it.
    const auto& slider = inspectorLayout.at("Animation time");
    const float y = slider.center().y;
    drag(ImVec2(slider.min.x + 2.0f, y), ImVec2(0.5f * (slider.min.x + slider.max.x), y));
    const content::AnimationPlayer& scrubbed = registry.get<content::AnimationPlayer>(floor);
    EXPECT_FALSE(scrubbed.playing);
    EXPECT_GT(scrubbed.time, 0.5f);
    EXPECT_LT(scrubbed.time, 1.5f);
    EXPECT_EQ(scrubbed.clip, 0);
    EXPECT_EQ(scene->commands().undoCount(), 0u) << "playback state is not a scene edit";
}

}  // namespace
}  // namespace candela::editor
