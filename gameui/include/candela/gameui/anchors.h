#pragma once
// Where a widget sits in its parent, the way Godot's controls anchor: each edge is a fraction
// of the parent's size (0 the parent's left or top, 1 its right or bottom) plus an offset in UI
// units, which the UI scale turns into pixels. A layout so made survives any window size:
//
//   top-right corner, 200 x 60 units:  anchors {1, 0, 1, 0}, offsets {-220, 20, -20, 80}
//   centred, 300 x 200 units:         anchors {0.5, 0.5, 0.5, 0.5}, offsets {-150, -100, 150, 100}
//   stretched along the bottom:       anchors {0, 1, 1, 1}, offsets {20, -80, -20, -20}
namespace candela::gameui {

struct Rect {
    float x = 0, y = 0, width = 0, height = 0;  // pixels, origin top-left, y down

    bool contains(float px, float py) const {
        return px >= x && py >= y && px < x + width && py < y + height;
    }
};

struct Anchors {
    float left = 0, top = 0, right = 1, bottom = 1;  // the default fills the parent
};

struct Offsets {
    float left = 0, top = 0, right = 0, bottom = 0;  // UI units (pixels at scale 1)
};

// A negative size (offsets that cross) collapses to zero at the left or top edge.
inline Rect place(const Rect& parent, const Anchors& a, const Offsets& o, float scale) {
    const float left = parent.x + a.left * parent.width + o.left * scale;
    const float top = parent.y + a.top * parent.height + o.top * scale;
    const float right = parent.x + a.right * parent.width + o.right * scale;
    const float bottom = parent.y + a.bottom * parent.height + o.bottom * scale;
    return {left, top, right > left ? right - left : 0.0f, bottom > top ? bottom - top : 0.0f};
}

}  // namespace candela::gameui
