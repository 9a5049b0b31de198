#include "candela/gameui/widget_tree.h"

#include <algorithm>
#include <cmath>

namespace candela::gameui {
namespace {

Widget make(WidgetKind kind, Anchors anchors, Offsets offsets) {
    Widget w;
    w.kind = kind;
    w.anchors = anchors;
    w.offsets = offsets;
    return w;
}

}  // namespace

Widget panel(Anchors anchors, Offsets offsets) {
    Widget w = make(WidgetKind::Panel, anchors, offsets);
    w.color = {0.05f, 0.05f, 0.08f, 0.8f};
    return w;
}

Widget label(std::string text, Anchors anchors, Offsets offsets) {
    Widget w = make(WidgetKind::Label, anchors, offsets);
    w.text = std::move(text);
    return w;
}

Widget image(std::string path, Anchors anchors, Offsets offsets) {
    Widget w = make(WidgetKind::Image, anchors, offsets);
    w.image = std::move(path);
    w.color = {1, 1, 1, 1};
    return w;
}

Widget button(std::string text, Anchors anchors, Offsets offsets) {
    Widget w = make(WidgetKind::Button, anchors, offsets);
    w.text = std::move(text);
    w.style.align = TextAlign::Center;
    w.color = {0.2f, 0.25f, 0.35f, 1.0f};
    return w;
}

Widget slider(float value, float minimum, float maximum, Anchors anchors, Offsets offsets) {
    Widget w = make(WidgetKind::Slider, anchors, offsets);
    w.minimum = minimum;
    w.maximum = maximum;
    w.value = std::clamp(value, minimum, maximum);
    w.step = (maximum - minimum) / 10.0f;
    return w;
}

Widget list(std::vector<std::string> items, Anchors anchors, Offsets offsets) {
    Widget w = make(WidgetKind::List, anchors, offsets);
    w.items = std::move(items);
    return w;
}

WidgetId WidgetTree::add(Widget widget, WidgetId parent) {
    nodes_.push_back({std::move(widget), parent < nodes_.size() ? parent : kNoWidget, {}});
    return WidgetId(nodes_.size() - 1);
}

// Parents come before their children (add() takes an existing parent), so one pass places all.
void WidgetTree::layout(float width, float height) {
    scale_ = height > 0 ? height / kReferenceHeight : 1.0f;
    const Rect window{0, 0, width, height};
    for (Node& n : nodes_) {
        const Rect& parent = n.parent == kNoWidget ? window : nodes_[n.parent].rect;
        n.rect = place(parent, n.widget.anchors, n.widget.offsets, scale_);
    }
}

bool WidgetTree::shown(WidgetId id) const {
    for (; id != kNoWidget; id = nodes_[id].parent) {
        if (!nodes_[id].widget.visible) return false;
    }
    return true;
}

bool WidgetTree::focusable(WidgetId id) const {
    const Widget& w = nodes_[id].widget;
    return (w.kind == WidgetKind::Button || w.kind == WidgetKind::Slider ||
            w.kind == WidgetKind::List) &&
           w.enabled && shown(id);
}

// The topmost (last added) focusable widget under the point.
WidgetId WidgetTree::hit(float x, float y) const {
    for (WidgetId id = WidgetId(nodes_.size()); id-- > 0;) {
        if (focusable(id) && nodes_[id].rect.contains(x, y)) return id;
    }
    return kNoWidget;
}

void WidgetTree::moveFocus(int direction) {
    const auto count = static_cast<std::int64_t>(nodes_.size());
    std::int64_t at = focus_ == kNoWidget ? (direction > 0 ? -1 : count) : std::int64_t(focus_);
    for (std::int64_t step = 0; step < count; ++step) {
        at = (at + direction + count) % count;
        if (focusable(WidgetId(at))) {
            focus_ = WidgetId(at);
            return;
        }
    }
}

void WidgetTree::nudge(WidgetId id, int direction, std::vector<UiEvent>& events) {
    Widget& w = nodes_[id].widget;
    const float value = std::clamp(w.value + float(direction) * w.step, w.minimum, w.maximum);
    if (value != w.value) {
        w.value = value;
        events.push_back({id, UiEvent::Type::ValueChanged, value, -1});
    }
}

std::vector<UiEvent> WidgetTree::update(const UiInput& in) {
    std::vector<UiEvent> events;
    if (focus_ != kNoWidget && (focus_ >= nodes_.size() || !focusable(focus_))) focus_ = kNoWidget;
    hover_ = hit(in.pointerX, in.pointerY);
    // Pointer.
    if (in.pointerPressed && hover_ != kNoWidget) {
        pressed_ = focus_ = hover_;
        Node& n = nodes_[hover_];
        if (n.widget.kind == WidgetKind::List && !n.widget.items.empty()) {
            const float row = listRowHeight(n.widget, scale_);
            const auto item = std::int32_t((in.pointerY - n.rect.y) / row);
            if (item >= 0 && item < std::int32_t(n.widget.items.size())) {
                n.widget.selected = item;
                events.push_back({hover_, UiEvent::Type::Chosen, 0, item});
            }
        }
    }
    if (pressed_ != kNoWidget && in.pointerDown) {
        Widget& w = nodes_[pressed_].widget;
        const Rect& r = nodes_[pressed_].rect;
        if (w.kind == WidgetKind::Slider && r.width > 0) {
            const float t = std::clamp((in.pointerX - r.x) / r.width, 0.0f, 1.0f);
            const float value = w.minimum + t * (w.maximum - w.minimum);
            if (value != w.value) {
                w.value = value;
                events.push_back({pressed_, UiEvent::Type::ValueChanged, value, -1});
            }
        }
    }
    if (in.pointerReleased) {
        if (pressed_ != kNoWidget && pressed_ == hover_ &&
            nodes_[pressed_].widget.kind == WidgetKind::Button) {
            events.push_back({pressed_, UiEvent::Type::Clicked, 0, -1});
        }
        pressed_ = kNoWidget;
    }
    // Keys and gamepad.
    const int vertical = int(in.down) - int(in.up);
    if (vertical != 0) {
        Widget* focusedList = focus_ != kNoWidget && nodes_[focus_].widget.kind == WidgetKind::List
                                  ? &nodes_[focus_].widget
                                  : nullptr;
        const std::int32_t next = focusedList ? focusedList->selected + vertical : -1;
        if (focusedList && next >= 0 && next < std::int32_t(focusedList->items.size())) {
            focusedList->selected = next;  // within the list first
        } else {
            moveFocus(vertical);
        }
    }
    const int horizontal = int(in.right) - int(in.left);
    if (horizontal != 0 && focus_ != kNoWidget && nodes_[focus_].widget.kind == WidgetKind::Slider)
        nudge(focus_, horizontal, events);
    if (in.accept && focus_ != kNoWidget) {
        const Widget& w = nodes_[focus_].widget;
        if (w.kind == WidgetKind::Button) events.push_back({focus_, UiEvent::Type::Clicked, 0, -1});
        if (w.kind == WidgetKind::List && !w.items.empty())
            events.push_back({focus_, UiEvent::Type::Chosen, 0, w.selected});
    }
    return events;
}

}  // namespace candela::gameui
