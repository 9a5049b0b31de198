#include "orb_ui.h"

#include <cmath>
#include <cstdio>
#include <memory>

#include "candela/gameui/widget_tree.h"
#include "candela/runtime/game_ui.h"
#include "orb_components.h"

namespace orb {
namespace {

using namespace candela::gameui;
using candela::runtime::FrameContext;
using candela::runtime::SceneWorld;

struct Screens {
    std::shared_ptr<candela::runtime::GameUi> ui;
    WidgetId title = kNoWidget, play = kNoWidget, quit = kNoWidget;
    WidgetId scorePanel = kNoWidget, score = kNoWidget, result = kNoWidget;
};

Screens build(std::shared_ptr<candela::runtime::GameUi> ui) {
    Screens s;
    s.ui = std::move(ui);
    WidgetTree& tree = s.ui->tree();
    const Anchors centre{0.5f, 0.5f, 0.5f, 0.5f};
    s.title = tree.add(panel(centre, {-180, -150, 180, 150}));
    Widget name = label("Orb", {0, 0, 1, 0}, {0, 20, 0, 90});
    name.style = {.pixelSize = 56, .align = TextAlign::Center};
    name.textColor = {1.0f, 0.85f, 0.55f, 1.0f};
    tree.add(name, s.title);
    Widget hint =
        label("Collect every spark before the time runs out", {0, 0, 1, 0}, {20, 90, -20, 150});
    hint.style = {.pixelSize = 20, .align = TextAlign::Center};
    tree.add(hint, s.title);
    s.play = tree.add(button("Play", {0, 1, 1, 1}, {60, -130, -60, -80}), s.title);
    s.quit = tree.add(button("Quit", {0, 1, 1, 1}, {60, -70, -60, -20}), s.title);
    s.scorePanel = tree.add(panel({1, 0, 1, 0}, {-470, 16, -16, 64}));
    Widget score = label("", {0, 0, 1, 1}, {12, 0, -12, 0});
    score.style = {.pixelSize = 22, .align = TextAlign::Right};
    s.score = tree.add(score, s.scorePanel);
    Widget result = label("", {0, 0.5f, 1, 0.5f}, {0, -40, 0, 40});
    result.style = {.pixelSize = 32, .align = TextAlign::Center};
    s.result = tree.add(result);
    return s;
}

GameState* stateOf(SceneWorld& world) {
    GameState* state = nullptr;
    world.registry.view<GameState>().each([&](GameState& s) { state = &s; });
    return state;
}

}  // namespace

void addOrbUi(candela::runtime::Application& app, bool showTitle) {
    auto screens = std::make_shared<Screens>(build(std::make_shared<candela::runtime::GameUi>()));
    app.addLayer(screens->ui);
    if (GameState* state = stateOf(app.world()); state && showTitle) state->status = Status::Title;
    // Before the game's systems: Play starts the clock this frame.
    app.addSystem("menu", [&app, screens](SceneWorld& world, const FrameContext&) {
        GameState* state = stateOf(world);
        if (!state) return;
        for (const UiEvent& e : screens->ui->events()) {
            if (e.type != UiEvent::Type::Clicked || state->status != Status::Title) continue;
            if (e.widget == screens->play) {
                state->status = Status::Playing;
                std::printf("play\n");
            }
            if (e.widget == screens->quit) app.requestQuit();
        }
        WidgetTree& tree = screens->ui->tree();
        const bool title = state->status == Status::Title;
        tree.widget(screens->title).visible = title;
        screens->ui->interactive = title;
        if (title && tree.focused() == kNoWidget) tree.focus(screens->play);
        tree.widget(screens->scorePanel).visible = !title;
        char text[96];
        std::snprintf(text, sizeof text, "Score %d   Sparks %d/%d   %.0f s", state->score,
                      state->collected, state->total,
                      std::ceil(std::max(0.0, state->timeLimitSeconds - state->elapsedSeconds)));
        tree.widget(screens->score).text = text;
        Widget& result = tree.widget(screens->result);
        result.visible = state->status == Status::Won || state->status == Status::Lost;
        if (result.visible) {
            result.text = state->status == Status::Won
                              ? "You won with " + std::to_string(state->score) +
                                    " points! R or Start to play again"
                              : "You lost: " + state->reason + ". R or Start to try again";
        }
    });
}

}  // namespace orb
