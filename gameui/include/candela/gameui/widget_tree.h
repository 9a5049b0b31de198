#pragma once
// A small retained widget set for game menus and HUDs: panels, labels, images, buttons,
// sliders and lists, anchored in their parents (anchors.h), navigated by pointer, keyboard or
// gamepad through UiInput (the application fills it from its input actions). The tree lays itself
// out for the window's size and reports what the player did as events; drawing is the UI pass's.
//
//   WidgetTree ui;
//   WidgetId menu = ui.add(panel({0.5f, 0.5f, 0.5f, 0.5f}, {-160, -120, 160, 120}));
//   WidgetId play = ui.add(button("Play", {0, 0, 1, 0}, {20, 20, -20, 70}), menu);
//   ui.layout(width, height);
//   for (const UiEvent& e : ui.update(input)) if (e.widget == play) startGame();
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "candela/gameui/anchors.h"
#include "candela/gameui/text_layout.h"

namespace candela::gameui {

using WidgetId = std::uint32_t;
inline constexpr WidgetId kNoWidget = ~0u;
// UI units are pixels of a window this tall: the UI scale is the window's height over it.
inline constexpr float kReferenceHeight = 720.0f;

enum class WidgetKind : std::uint8_t { Panel, Label, Image, Button, Slider, List };

struct Widget {
    WidgetKind kind = WidgetKind::Panel;
    Anchors anchors;
    Offsets offsets;
    std::string text;                     // a label's or button's
    TextStyle style{.pixelSize = 24.0f};  // the size in UI units
    // Display-encoded RGBA (the LDR target holds sRGB-encoded values): the fill (a label has
    // none) and the text.
    std::array<float, 4> color{0, 0, 0, 0};
    std::array<float, 4> textColor{1, 1, 1, 1};
    std::string image;  // an image widget's PNG or JPEG, stretched over its rect, tinted by color
    float value = 0, minimum = 0, maximum = 1, step = 0.1f;  // a slider's
    std::vector<std::string> items;                          // a list's
    std::int32_t selected = 0;                               // the list's chosen item
    bool visible = true;
    bool enabled = true;
};

// A list's row height in pixels: one and a half times its text size, at the UI scale. The hit
// test and the draw list both place rows by it.
inline float listRowHeight(const Widget& list, float scale) {
    return 1.5f * list.style.pixelSize * scale;
}

Widget panel(Anchors anchors, Offsets offsets);
Widget label(std::string text, Anchors anchors, Offsets offsets);
Widget image(std::string path, Anchors anchors, Offsets offsets);
Widget button(std::string text, Anchors anchors, Offsets offsets);
Widget slider(float value, float minimum, float maximum, Anchors anchors, Offsets offsets);
Widget list(std::vector<std::string> items, Anchors anchors, Offsets offsets);

// One frame of what the player does to the UI, in window pixels.
struct UiInput {
    float pointerX = -1, pointerY = -1;
    bool pointerDown = false;
    bool pointerPressed = false;                                 // went down this frame
    bool pointerReleased = false;                                // went up this frame
    bool up = false, down = false, left = false, right = false;  // pressed this frame
    bool accept = false;  // Enter, the gamepad's A: pressed this frame
};

struct UiEvent {
    enum class Type : std::uint8_t { Clicked, ValueChanged, Chosen };
    WidgetId widget = kNoWidget;
    Type type = Type::Clicked;
    float value = 0;         // a slider's new value
    std::int32_t item = -1;  // a list's chosen item
};

class WidgetTree {
public:
    WidgetId add(Widget widget, WidgetId parent = kNoWidget);
    Widget& widget(WidgetId id) { return nodes_.at(id).widget; }
    const Widget& widget(WidgetId id) const { return nodes_.at(id).widget; }
    std::size_t size() const { return nodes_.size(); }

    // Places every widget for a window of `width` x `height` pixels.
    void layout(float width, float height);
    const Rect& rect(WidgetId id) const { return nodes_.at(id).rect; }
    // It and every ancestor visible.
    bool shown(WidgetId id) const;
    float scale() const { return scale_; }

    // Pointer: a button clicks when pressed and released over it; a slider follows the pointer
    // while held; a list chooses the item clicked. Keys and gamepad: up and down move the focus
    // among visible, enabled buttons, sliders and lists (in the order added), accept clicks or
    // chooses, left and right step a slider or move a list's selection.
    std::vector<UiEvent> update(const UiInput& input);
    WidgetId focused() const { return focus_; }
    void focus(WidgetId id) { focus_ = id; }
    WidgetId hovered() const { return hover_; }
    WidgetId pressed() const { return pressed_; }  // held by the pointer

private:
    struct Node {
        Widget widget;
        WidgetId parent = kNoWidget;
        Rect rect;
    };
    bool focusable(WidgetId id) const;
    WidgetId hit(float x, float y) const;
    void moveFocus(int direction);
    void nudge(WidgetId id, int direction, std::vector<UiEvent>& events);

    std::vector<Node> nodes_;
    float scale_ = 1.0f;
    WidgetId focus_ = kNoWidget, hover_ = kNoWidget, pressed_ = kNoWidget;
};

}  // namespace candela::gameui
