// Widgets: anchored layouts that survive resizing, and buttons, sliders and lists driven by a
// pointer and by keys or a gamepad, each action firing exactly once.
#include <gtest/gtest.h>

#include <algorithm>

#include "candela/gameui/widget_tree.h"

namespace candela::gameui {
namespace {

// A click at the centre of `r`: pressed on one frame, released on the next.
std::vector<UiEvent> clickAt(WidgetTree& ui, const Rect& r) {
    const float x = r.x + r.width / 2, y = r.y + r.height / 2;
    std::vector<UiEvent> events =
        ui.update({.pointerX = x, .pointerY = y, .pointerDown = true, .pointerPressed = true});
    const std::vector<UiEvent> more =
        ui.update({.pointerX = x, .pointerY = y, .pointerReleased = true});
    events.insert(events.end(), more.begin(), more.end());
    return events;
}

int count(const std::vector<UiEvent>& events, WidgetId id, UiEvent::Type type) {
    return int(std::count_if(events.begin(), events.end(),
                             [&](const UiEvent& e) { return e.widget == id && e.type == type; }));
}

TEST(WidgetTree, AnchoredLayoutsSurviveEveryWindowSize) {
    WidgetTree ui;
    const WidgetId score = ui.add(label("score", {1, 0, 1, 0}, {-220, 20, -20, 80}));  // top right
    const WidgetId menu =
        ui.add(panel({0.5f, 0.5f, 0.5f, 0.5f}, {-150, -100, 150, 100}));  // centred
    const WidgetId play = ui.add(button("Play", {0, 0, 1, 0}, {20, 20, -20, 70}), menu);
    for (auto [w, h] :
         {std::pair{640.0f, 360.0f}, {1280.0f, 720.0f}, {1920.0f, 1080.0f}, {800.0f, 1000.0f}}) {
        SCOPED_TRACE(std::to_string(int(w)) + "x" + std::to_string(int(h)));
        ui.layout(w, h);
        const float s = h / kReferenceHeight;
        EXPECT_NEAR(ui.rect(score).x + ui.rect(score).width, w - 20 * s, 1e-3);
        EXPECT_NEAR(ui.rect(score).y, 20 * s, 1e-3);
        EXPECT_NEAR(ui.rect(score).width, 200 * s, 1e-3);
        EXPECT_NEAR(ui.rect(menu).x + ui.rect(menu).width / 2, w / 2, 1e-3);
        EXPECT_NEAR(ui.rect(menu).y + ui.rect(menu).height / 2, h / 2, 1e-3);
        EXPECT_NEAR(ui.rect(play).x, ui.rect(menu).x + 20 * s, 1e-3);
        EXPECT_NEAR(ui.rect(play).width, ui.rect(menu).width - 40 * s, 1e-3);
    }
}

TEST(WidgetTree, AButtonClickedByThePointerFiresOnce) {
    WidgetTree ui;
    const WidgetId play = ui.add(button("Play", {0.5f, 0.5f, 0.5f, 0.5f}, {-100, -25, 100, 25}));
    ui.layout(1280, 720);
    EXPECT_EQ(count(clickAt(ui, ui.rect(play)), play, UiEvent::Type::Clicked), 1);
    // Held down over several frames, then released: still one click, on release.
    const Rect r = ui.rect(play);
    const float x = r.x + 5, y = r.y + 5;
    int clicks = count(
        ui.update({.pointerX = x, .pointerY = y, .pointerDown = true, .pointerPressed = true}),
        play, UiEvent::Type::Clicked);
    for (int f = 0; f < 5; ++f)
        clicks += count(ui.update({.pointerX = x, .pointerY = y, .pointerDown = true}), play,
                        UiEvent::Type::Clicked);
    EXPECT_EQ(clicks, 0);
    EXPECT_EQ(ui.pressed(), play);
    clicks += count(ui.update({.pointerX = x, .pointerY = y, .pointerReleased = true}), play,
                    UiEvent::Type::Clicked);
    EXPECT_EQ(clicks, 1);
    // Pressed on it and released elsewhere: no click (the player changed their mind).
    ui.update({.pointerX = x, .pointerY = y, .pointerDown = true, .pointerPressed = true});
    EXPECT_EQ(count(ui.update({.pointerX = 5, .pointerY = 5, .pointerReleased = true}), play,
                    UiEvent::Type::Clicked),
              0);
}

TEST(WidgetTree, GamepadFocusMovesAmongButtonsAndAcceptFiresOnce) {
    WidgetTree ui;
    const WidgetId menu = ui.add(panel({0.5f, 0.5f, 0.5f, 0.5f}, {-150, -100, 150, 100}));
    ui.add(label("Orb", {0, 0, 1, 0}, {0, 0, 0, 40}), menu);
    const WidgetId play = ui.add(button("Play", {0, 0, 1, 0}, {20, 50, -20, 90}), menu);
    const WidgetId quit = ui.add(button("Quit", {0, 0, 1, 0}, {20, 100, -20, 140}), menu);
    ui.layout(1280, 720);
    EXPECT_EQ(ui.focused(), kNoWidget);
    ui.update({.down = true});
    EXPECT_EQ(ui.focused(), play) << "the label is skipped";
    ui.update({.down = true});
    EXPECT_EQ(ui.focused(), quit);
    ui.update({.down = true});
    EXPECT_EQ(ui.focused(), play) << "wraps around";
    EXPECT_EQ(count(ui.update({.accept = true}), play, UiEvent::Type::Clicked), 1);
    EXPECT_TRUE(ui.update({}).empty()) << "nothing more without another press";
    // A hidden menu's buttons cannot be focused or clicked.
    ui.widget(menu).visible = false;
    EXPECT_TRUE(ui.update({.accept = true}).empty());
    ui.update({.down = true});
    EXPECT_EQ(ui.focused(), kNoWidget);
    EXPECT_TRUE(clickAt(ui, ui.rect(quit)).empty());
}

TEST(WidgetTree, SlidersStepWithTheGamepadAndFollowThePointer) {
    WidgetTree ui;
    const WidgetId volume = ui.add(slider(0.5f, 0.0f, 1.0f, {0, 0, 0, 0}, {100, 100, 300, 130}));
    ui.layout(1280, 720);
    ui.focus(volume);
    std::vector<UiEvent> e = ui.update({.right = true});
    ASSERT_EQ(e.size(), 1u);
    EXPECT_NEAR(e[0].value, 0.6f, 1e-6);
    for (int i = 0; i < 10; ++i)
        ui.update({.right = true});
    EXPECT_EQ(ui.widget(volume).value, 1.0f) << "clamped at the maximum";
    EXPECT_TRUE(ui.update({.right = true}).empty()) << "no change, no event";
    const Rect& r = ui.rect(volume);
    ui.update({.pointerX = r.x + r.width / 4,
               .pointerY = r.y + 1,
               .pointerDown = true,
               .pointerPressed = true});
    EXPECT_NEAR(ui.widget(volume).value, 0.25f, 1e-5);
    ui.update({.pointerX = r.x + r.width * 2, .pointerY = r.y + 1, .pointerDown = true});
    EXPECT_EQ(ui.widget(volume).value, 1.0f) << "dragged past the end";
}

TEST(WidgetTree, AListIsAMenuForPointerAndGamepad) {
    WidgetTree ui;
    const WidgetId levels =
        ui.add(list({"Easy", "Normal", "Hard"}, {0, 0, 0, 0}, {100, 100, 400, 300}));
    ui.layout(1280, 720);
    ui.update({.down = true});
    ASSERT_EQ(ui.focused(), levels);
    ui.update({.down = true});
    EXPECT_EQ(ui.widget(levels).selected, 1);
    std::vector<UiEvent> e = ui.update({.accept = true});
    ASSERT_EQ(count(e, levels, UiEvent::Type::Chosen), 1);
    EXPECT_EQ(e[0].item, 1);
    // The third row, clicked: 1.5 x 24 units a row at scale 1.
    e = ui.update({.pointerX = 150,
                   .pointerY = 100 + 36 * 2 + 10,
                   .pointerDown = true,
                   .pointerPressed = true});
    ASSERT_EQ(e.size(), 1u);
    EXPECT_EQ(e[0].item, 2);
    EXPECT_EQ(ui.widget(levels).selected, 2);
}

}  // namespace
}  // namespace candela::gameui
