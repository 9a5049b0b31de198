#include "candela/runtime/game_ui.h"

#include <cstdio>

#include "candela/gameui/glyph_atlas.h"
#include "candela/gameui/ui_draw_list.h"
#include "candela/runtime/frame_context.h"
#include "candela/runtime/input_state.h"
#include "candela/runtime/layer_pass_context.h"
#include "candela/ui/game_ui_renderer.h"

namespace candela::runtime {
namespace {

gameui::UiInput uiInput(const InputState& in) {
    gameui::UiInput ui;
    ui.pointerX = in.mouseX;
    ui.pointerY = in.mouseY;
    ui.pointerDown = in.down(MouseButton::Left);
    ui.pointerPressed = in.pressed(MouseButton::Left);
    ui.up = in.pressed(Key::Up) || in.pressed(GamepadButton::DpadUp);
    ui.down = in.pressed(Key::Down) || in.pressed(GamepadButton::DpadDown);
    ui.left = in.pressed(Key::Left) || in.pressed(GamepadButton::DpadLeft);
    ui.right = in.pressed(Key::Right) || in.pressed(GamepadButton::DpadRight);
    ui.accept = in.pressed(Key::Enter) || in.pressed(Key::Space) || in.pressed(GamepadButton::A);
    return ui;
}

}  // namespace

struct GameUi::Gpu {
    std::unique_ptr<ui::GameUiRenderer> renderer;
    gameui::GlyphAtlas atlas;
    gameui::UiDrawList list;
    bool pointerWasDown = false;
};

GameUi::GameUi(std::shared_ptr<const gameui::Font> font) : font_(std::move(font)) {
    if (!font_) {
        content::Diagnostics diagnostics;
        font_ = gameui::Font::fallback(diagnostics);
        for (const content::Diagnostic& d : diagnostics.messages)
            std::fprintf(stderr, "%s\n", content::formatDiagnostic(d).c_str());
    }
}

GameUi::~GameUi() = default;

void GameUi::start(render::GpuContext& context, Window*) {
    gpu_ = std::make_unique<Gpu>();
    gpu_->renderer = std::make_unique<ui::GameUiRenderer>(context);
}

std::vector<render::TargetAccess> GameUi::uses() const {
    if (!gpu_ || gpu_->list.indices.empty()) return {};
    return {{render::FrameTarget::Ldr, render::TargetUse::ColorAttachment}};
}

void GameUi::prepare(const FrameContext& frame, const FrameStats&) {
    tree_.layout(float(frame.width), float(frame.height));
    events_.clear();
    if (interactive && frame.input) {
        gameui::UiInput input = uiInput(*frame.input);
        // A release is the frame the button is up after being down.
        input.pointerReleased = gpu_ && gpu_->pointerWasDown && !input.pointerDown;
        events_ = tree_.update(input);
    }
    if (!gpu_) return;
    gpu_->pointerWasDown = frame.input && frame.input->down(MouseButton::Left);
    gpu_->list.clear();
    if (font_) gameui::buildDrawList(tree_, *font_, gpu_->atlas, gpu_->list);
    for (const content::Diagnostic& d : gpu_->atlas.takeDiagnostics().messages)
        std::fprintf(stderr, "%s\n", content::formatDiagnostic(d).c_str());  // bad images, once
    gpu_->renderer->prepare(gpu_->atlas, gpu_->list);
}

void GameUi::record(LayerPassContext& pass) {
    if (gpu_)
        gpu_->renderer->recordInPass(pass.commandBuffer(), pass.image(render::FrameTarget::Ldr));
}

void GameUi::stop() {
    gpu_.reset();
}

}  // namespace candela::runtime
