#pragma once
// The game's own UI (gameui): a widget tree drawn by a pass after tonemapping, driven by the
// mouse, the keyboard and the first gamepad. Add it as a layer and build widgets on its tree:
//
//   auto ui = std::make_shared<runtime::GameUi>();
//   app.addLayer(ui);
//   gameui::WidgetTree& tree = ui->tree();
//   gameui::WidgetId play = tree.add(gameui::button("Play", {0.5f, 0.5f, 0.5f, 0.5f},
//                                                   {-100, -30, 100, 30}));
//   app.addSystem("menu", [&](runtime::SceneWorld&, const runtime::FrameContext&) {
//       for (const gameui::UiEvent& e : ui->events())
//           if (e.widget == play) startGame();
//   });
//
// Each frame, after the systems, the layer lays the tree out for the frame's size, turns the
// input into the tree's UiInput (pointer: the mouse and its left button; up/down/left/right:
// the arrow keys and the D-pad; accept: Enter, Space or the gamepad's A) and builds the draw
// list. Systems therefore see a frame's events one frame later, as they see physics events.
// The font: the given one, else the fallback (gameui/font.h).
#include <memory>
#include <vector>

#include "candela/gameui/font.h"
#include "candela/gameui/widget_tree.h"
#include "candela/runtime/frame_layer.h"

namespace candela::runtime {

class GameUi : public FrameLayer {
public:
    explicit GameUi(std::shared_ptr<const gameui::Font> font = nullptr);
    ~GameUi() override;

    gameui::WidgetTree& tree() { return tree_; }
    // What the player did to the UI in the last frame made.
    const std::vector<gameui::UiEvent>& events() const { return events_; }
    // False: the UI takes no input (a HUD during play); it is still drawn.
    bool interactive = true;

    std::string name() const override { return "game_ui"; }
    void start(render::GpuContext& context, Window* window) override;
    std::vector<render::TargetAccess> uses() const override;
    void prepare(const FrameContext& frame, const FrameStats& stats) override;
    void record(LayerPassContext& pass) override;
    void stop() override;

private:
    struct Gpu;
    std::shared_ptr<const gameui::Font> font_;
    gameui::WidgetTree tree_;
    std::vector<gameui::UiEvent> events_;
    std::unique_ptr<Gpu> gpu_;
};

}  // namespace candela::runtime
