// FrameLayer through the public API, headless on the device: a layer's pass runs inside the
// frame graph after tonemapping, with its image in the layout its declared use needs (no
// barrier of its own; validation, synchronization validation included, stays silent), its
// result is what the capture shows, and a layer that only reads is kept, not culled.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "candela/render/gpu_image.h"
#include "candela/runtime/application.h"
#include "candela/runtime/exit_code.h"
#include "candela/runtime/layer_pass_context.h"
#include "image_files.h"

using namespace candela;
using namespace candela::runtime;

namespace {

// Clears the LDR image to magenta as a colour attachment.
class ClearLdr : public FrameLayer {
public:
    int prepared = 0, recorded = 0;
    std::string name() const override { return "clear_ldr"; }
    void start(render::GpuContext&, Window*) override {}
    std::vector<render::TargetAccess> uses() const override {
        return {{render::FrameTarget::Ldr, render::TargetUse::ColorAttachment}};
    }
    void prepare(const FrameContext&, const FrameStats&) override { ++prepared; }
    void record(LayerPassContext& pass) override {
        ++recorded;
        VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        color.imageView = pass.image(render::FrameTarget::Ldr).view();
        color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        color.clearValue.color = {{1.0f, 0.0f, 1.0f, 1.0f}};
        VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
        rendering.renderArea = {{0, 0}, {pass.width(), pass.height()}};
        rendering.layerCount = 1;
        rendering.colorAttachmentCount = 1;
        rendering.pColorAttachments = &color;
        vkCmdBeginRendering(pass.commandBuffer(), &rendering);
        vkCmdEndRendering(pass.commandBuffer());
    }
    void stop() override {}
};

// Declares a read of the HDR image and records nothing: a pass nobody reads from.
class ReadHdr : public FrameLayer {
public:
    int recorded = 0;
    std::string name() const override { return "read_hdr"; }
    void start(render::GpuContext&, Window*) override {}
    std::vector<render::TargetAccess> uses() const override {
        return {{render::FrameTarget::Hdr, render::TargetUse::StorageRead}};
    }
    void prepare(const FrameContext&, const FrameStats&) override {}
    void record(LayerPassContext&) override { ++recorded; }
    void stop() override {}
};

}  // namespace

TEST(FrameLayer, APassOfTheGraphDrawsWhatTheCaptureShows) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                      ("candela_frame_layer_" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    ApplicationOptions options;
    options.headless = true;
    options.width = 64;
    options.height = 32;
    options.frames = 2;
    options.validation = validationModeFromEnvironment();
    options.captures.push_back({FrameCapture::kLastFrame, dir / "layer.png"});
    options.stats = dir / "stats.json";
    options.frameGraph = dir / "graph.dot";
    Application app(options);
    app.setWorld(nullptr);  // the background only: the layer's colour is all that can be magenta
    auto clear = std::make_shared<ClearLdr>();
    auto read = std::make_shared<ReadHdr>();
    app.addLayer(clear);
    app.addLayer(read);
    ASSERT_EQ(app.run(), kExitOk);
    EXPECT_EQ(clear->prepared, 2);
    EXPECT_EQ(clear->recorded, 2);
    EXPECT_EQ(read->recorded, 2) << "a layer that only reads was culled";

    std::string error;
    std::optional<golden::LdrImage> image = golden::readLdrPng(dir / "layer.png", error);
    ASSERT_TRUE(image) << error;
    size_t magenta = 0;
    for (size_t i = 0; i < image->pixelCount(); ++i) {
        magenta +=
            image->rgb[3 * i] == 255 && image->rgb[3 * i + 1] == 0 && image->rgb[3 * i + 2] == 255;
    }
    EXPECT_EQ(magenta, image->pixelCount());

    std::ifstream statsFile(dir / "stats.json");
    const nlohmann::json stats = nlohmann::json::parse(statsFile);
    EXPECT_TRUE(stats["passes"].contains("clear_ldr")) << stats["passes"].dump();
    EXPECT_TRUE(stats["passes"].contains("read_hdr")) << stats["passes"].dump();
    std::ifstream dotFile(dir / "graph.dot");
    const std::string dot((std::istreambuf_iterator<char>(dotFile)),
                          std::istreambuf_iterator<char>());
    EXPECT_LT(dot.find("tonemap"), dot.find("clear_ldr")) << dot;
    std::filesystem::remove_all(dir);
}
