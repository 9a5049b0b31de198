// Compile-only tests of the frame graph: ordering, culling, barrier lists, aliasing and the
// errors. No GPU: compileFrameGraph is pure bookkeeping over the declarations.
#include <gtest/gtest.h>

#include <random>

#include "candela/render/gpu_buffer.h"
#include "frame_graph/frame_graph.h"
#include "frame_graph/transient_placement.h"

namespace candela::render {
namespace {

std::vector<std::string> orderNames(const FrameGraph& g, const CompiledFrameGraph& c) {
    std::vector<std::string> names;
    for (uint32_t p : c.order)
        names.push_back(g.passes()[p].name);
    return names;
}

ImageDesc colorDesc(uint32_t size = 64) {
    return {VK_FORMAT_R8G8B8A8_UNORM,
            size,
            size,
            1,
            false,
            VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT};
}

const ImageState kTransferSrcAtEnd{VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                   VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT};

std::string compileError(const FrameGraph& g) {
    try {
        compileFrameGraph(g);
    } catch (const FrameGraphError& e) {
        return e.what();
    }
    return "";
}

TEST(FrameGraph, OrdersWriteAfterReadBeforeTheWriterWhateverTheDeclarationOrder) {
    FrameGraph g;
    ResourceHandle out = g.importImage("out", nullptr, {}, kTransferSrcAtEnd);
    ResourceHandle buffer = g.createBuffer("buffer", 256, 0);
    auto fill = g.addPass("fill", PassKind::Device, nullptr);
    ResourceHandle filled = fill.write(buffer, Use::TransferDst);
    // Declared before its reader, but it overwrites what the reader reads.
    auto overwrite = g.addPass("overwrite", PassKind::Device, nullptr);
    ResourceHandle second = overwrite.write(filled, Use::StorageWrite);
    auto reader = g.addPass("reader", PassKind::Device, nullptr);
    reader.read(filled, Use::StorageRead);
    reader.write(out, Use::StorageWrite);
    auto last = g.addPass("last", PassKind::Device, nullptr);
    last.read(second, Use::StorageRead);
    last.sideEffect();
    const CompiledFrameGraph c = compileFrameGraph(g);
    EXPECT_EQ(orderNames(g, c), (std::vector<std::string>{"fill", "reader", "overwrite", "last"}));
}

TEST(FrameGraph, CullsPassesWhoseResultsNobodyReads) {
    FrameGraph g;
    ResourceHandle out = g.importImage("out", nullptr, {}, kTransferSrcAtEnd);
    ResourceHandle unused = g.createImage("unused", colorDesc());
    ResourceHandle chain = g.createBuffer("chain", 64, 0);
    auto kept = g.addPass("kept", PassKind::Device, nullptr);
    kept.write(out, Use::StorageWrite);
    auto feedsCulled = g.addPass("feeds_culled", PassKind::Device, nullptr);
    ResourceHandle chain1 = feedsCulled.write(chain, Use::StorageWrite);
    auto culled = g.addPass("culled", PassKind::Device, nullptr);
    culled.read(chain1, Use::StorageRead);
    culled.write(unused, Use::ColorAttachment);
    auto host = g.addPass("host_side_effect", PassKind::Host, nullptr);
    host.read(chain1, Use::HostRead);
    host.sideEffect();
    CompiledFrameGraph c = compileFrameGraph(g);
    EXPECT_EQ(orderNames(g, c),
              (std::vector<std::string>{"kept", "feeds_culled", "host_side_effect"}));
    EXPECT_TRUE(c.culled[2]);
    EXPECT_EQ(c.lifetimes[unused.id].first, -1);  // never allocated

    // Without the host pass, the producer goes too.
    g.passes()[3].sideEffect = false;
    c = compileFrameGraph(g);
    EXPECT_EQ(orderNames(g, c), (std::vector<std::string>{"kept"}));
}

TEST(FrameGraph, BarrierListsOfADeferredFrame) {
    FrameGraph g;
    ResourceHandle hdr = g.importImage("hdr", nullptr, {}, kTransferSrcAtEnd);
    ResourceHandle albedo = g.createImage("albedo", colorDesc());
    ResourceHandle depth = g.createImage(
        "depth", {VK_FORMAT_D32_SFLOAT, 64, 64, 1, false,
                  VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT});
    ResourceHandle masks = g.importBuffer("masks", nullptr);

    auto gbuffer = g.addPass("gbuffer", PassKind::Device, nullptr);
    albedo = gbuffer.write(albedo, Use::ColorAttachment);
    depth = gbuffer.write(depth, Use::DepthWrite);
    hdr = gbuffer.write(hdr, Use::ColorAttachment);
    auto occupancy = g.addPass("occupancy", PassKind::Device, nullptr);
    occupancy.read(depth, Use::Sampled);
    masks = occupancy.write(masks, Use::StorageWrite);
    auto lighting = g.addPass("lighting", PassKind::Device, nullptr);
    lighting.read(albedo, Use::Sampled);
    lighting.read(depth, Use::Sampled);
    lighting.read(masks, Use::StorageRead);
    hdr = lighting.write(hdr, Use::StorageReadWrite);
    const CompiledFrameGraph c = compileFrameGraph(g);
    ASSERT_EQ(orderNames(g, c), (std::vector<std::string>{"gbuffer", "occupancy", "lighting"}));

    // gbuffer: three transitions out of UNDEFINED, nothing to wait for.
    ASSERT_EQ(c.before[0].images.size(), 3u);
    EXPECT_FALSE(c.before[0].hasMemoryBarrier());
    for (const ImageBarrier& b : c.before[0].images) {
        EXPECT_EQ(b.oldLayout, VK_IMAGE_LAYOUT_UNDEFINED);
        EXPECT_EQ(b.srcAccess, 0u);
    }
    // occupancy: depth to shader-read after the depth writes.
    ASSERT_EQ(c.before[1].images.size(), 1u);
    const ImageBarrier& d = c.before[1].images[0];
    EXPECT_EQ(d.resource, depth.id);
    EXPECT_EQ(d.oldLayout, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);
    EXPECT_EQ(d.newLayout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    EXPECT_EQ(d.srcAccess, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
    EXPECT_EQ(d.dstStages, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
    EXPECT_EQ(d.dstAccess, VK_ACCESS_2_SHADER_READ_BIT);
    // lighting: albedo and hdr change layout; depth is already readable by compute; the
    // masks need one memory barrier (storage write -> storage read).
    ASSERT_EQ(c.before[2].images.size(), 2u);
    EXPECT_TRUE(c.before[2].hasMemoryBarrier());
    EXPECT_EQ(c.before[2].memorySrcAccess, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    EXPECT_EQ(c.before[2].memoryDstAccess, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
    for (const ImageBarrier& b : c.before[2].images) {
        EXPECT_NE(b.resource, depth.id);
        if (b.resource == hdr.id) {
            EXPECT_EQ(b.oldLayout, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
            EXPECT_EQ(b.newLayout, VK_IMAGE_LAYOUT_GENERAL);
            EXPECT_EQ(b.srcAccess, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
        }
    }
    // End of frame: hdr to TRANSFER_SRC for the capture after the lighting writes.
    ASSERT_EQ(c.atEnd.images.size(), 1u);
    EXPECT_EQ(c.atEnd.images[0].oldLayout, VK_IMAGE_LAYOUT_GENERAL);
    EXPECT_EQ(c.atEnd.images[0].newLayout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    EXPECT_EQ(c.atEnd.images[0].srcAccess, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    EXPECT_EQ(c.barrierCount, 3u + 1u + 3u + 1u);
}

TEST(FrameGraph, ReadsInTheSameStageNeedNoSecondBarrierAndHostReadsWaitForTheDevice) {
    FrameGraph g;
    ResourceHandle buffer = g.importBuffer("buffer", nullptr);
    auto write = g.addPass("write", PassKind::Device, nullptr);
    buffer = write.write(buffer, Use::StorageWrite);
    auto readA = g.addPass("read_a", PassKind::Device, nullptr);
    readA.read(buffer, Use::StorageRead);
    readA.sideEffect();
    auto readB = g.addPass("read_b", PassKind::Device, nullptr);
    readB.read(buffer, Use::StorageRead);
    readB.sideEffect();
    auto host = g.addPass("host", PassKind::Host, nullptr);
    host.read(buffer, Use::HostRead);
    host.sideEffect();
    const CompiledFrameGraph c = compileFrameGraph(g);
    ASSERT_EQ(c.order.size(), 4u);
    EXPECT_TRUE(c.before[1].hasMemoryBarrier());
    EXPECT_TRUE(c.before[2].empty());
    EXPECT_EQ(c.before[3].memoryDstStages, VK_PIPELINE_STAGE_2_HOST_BIT);
    EXPECT_EQ(c.before[3].memoryDstAccess, VK_ACCESS_2_HOST_READ_BIT);
    EXPECT_EQ(c.before[3].memorySrcAccess, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
}

// Issue 20: the skinning pass writes the deformed vertices in a compute shader; the shadow and
// G-buffer passes, declared first, draw them as vertex input. The graph runs skinning first
// and makes its writes visible to vertex attribute fetch, once for both readers.
TEST(FrameGraph, DeformedVerticesReachVertexInputThroughOneBarrier) {
    FrameGraph g;
    ResourceHandle deformed = g.importBuffer("deformed_vertices", nullptr);
    ResourceHandle atlas = g.importImage("shadow_atlas", nullptr, {}, {});
    ResourceHandle color = g.importImage("color", nullptr, {}, {});
    ResourceHandle written = deformed;
    written.version = 1;  // what the skinning pass below produces
    auto shadows = g.addPass("shadows", PassKind::Device, nullptr);
    shadows.read(written, Use::VertexInput);
    shadows.write(atlas, Use::DepthWrite);
    auto gbuffer = g.addPass("gbuffer", PassKind::Device, nullptr);
    gbuffer.read(written, Use::VertexInput);
    gbuffer.write(color, Use::ColorAttachment);
    auto skinning = g.addPass("skinning", PassKind::Device, nullptr);
    skinning.write(deformed, Use::StorageWrite);
    const CompiledFrameGraph c = compileFrameGraph(g);
    ASSERT_EQ(orderNames(g, c), (std::vector<std::string>{"skinning", "shadows", "gbuffer"}));
    EXPECT_EQ(c.before[1].memorySrcStages, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
    EXPECT_EQ(c.before[1].memorySrcAccess, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    EXPECT_TRUE(c.before[1].memoryDstStages & VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT);
    EXPECT_TRUE(c.before[1].memoryDstAccess & VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT);
    EXPECT_FALSE(c.before[2].memoryDstAccess & VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT)
        << "the second reader needs no second barrier";
}

TEST(FrameGraph, AWriteIsVisibleToALaterPassOnlyThroughABarrier) {
    // Lighting writes the HDR target as a storage image, tonemap reads it the same way: same
    // layout, same stage, yet the read needs a barrier.
    FrameGraph g;
    ResourceHandle hdr = g.importImage("hdr", nullptr, {}, {});
    ResourceHandle ldr = g.importImage("ldr", nullptr, {}, {});
    auto lighting = g.addPass("lighting", PassKind::Device, nullptr);
    hdr = lighting.write(hdr, Use::StorageReadWrite);
    auto tonemap = g.addPass("tonemap", PassKind::Device, nullptr);
    tonemap.read(hdr, Use::StorageRead);
    tonemap.write(ldr, Use::StorageWrite);
    const CompiledFrameGraph c = compileFrameGraph(g);
    ASSERT_EQ(c.order.size(), 2u);
    EXPECT_TRUE(c.before[1].hasMemoryBarrier());
    EXPECT_EQ(c.before[1].memorySrcAccess, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    EXPECT_EQ(c.before[1].memoryDstAccess, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
}

TEST(FrameGraph, OnePassMayUseABufferTwoWaysButNotAnImageInTwoLayouts) {
    FrameGraph g;
    ResourceHandle buffer = g.importBuffer("params", nullptr);
    ResourceHandle image = g.importImage("target", nullptr, {}, {});
    auto both = g.addPass("uniform_and_storage", PassKind::Device, nullptr);
    both.read(buffer, Use::Uniform);
    both.read(buffer, Use::StorageRead);
    both.sideEffect();
    EXPECT_EQ(compileError(g), "");
    auto twoLayouts = g.addPass("sampled_and_attachment", PassKind::Device, nullptr);
    twoLayouts.read(image, Use::Sampled);
    twoLayouts.write(image, Use::ColorAttachment);
    twoLayouts.sideEffect();
    const std::string error = compileError(g);
    EXPECT_NE(error.find("'sampled_and_attachment' uses 'target' in two image layouts"),
              std::string::npos)
        << error;
}

TEST(FrameGraph, AliasesTransientsWhoseLifetimesDoNotOverlap) {
    FrameGraph g;
    ResourceHandle out = g.importBuffer("out", nullptr);
    ResourceHandle a = g.createImage("a", colorDesc());
    ResourceHandle b = g.createImage("b", colorDesc());
    ResourceHandle c = g.createImage("c", colorDesc());
    for (ResourceDecl& r : g.resources())
        r.needs = {16384, 256, 0xff};
    auto p0 = g.addPass("make_a", PassKind::Device, nullptr);
    a = p0.write(a, Use::ColorAttachment);
    auto p1 = g.addPass("a_to_b", PassKind::Device, nullptr);
    p1.read(a, Use::Sampled, kFragmentStage);
    b = p1.write(b, Use::ColorAttachment);
    auto p2 = g.addPass("b_to_c", PassKind::Device, nullptr);
    p2.read(b, Use::Sampled, kFragmentStage);
    c = p2.write(c, Use::ColorAttachment);
    auto p3 = g.addPass("c_to_out", PassKind::Device, nullptr);
    p3.read(c, Use::Sampled);
    p3.write(out, Use::StorageWrite);
    const CompiledFrameGraph compiled = compileFrameGraph(g);
    // a and c never live together: they share bytes; b overlaps both and may not.
    EXPECT_EQ(compiled.poolOffset[a.id], compiled.poolOffset[c.id]);
    EXPECT_NE(compiled.poolOffset[a.id], compiled.poolOffset[b.id]);
    EXPECT_EQ(compiled.poolBytes, 2u * 16384u);
    EXPECT_EQ(compiled.unaliasedBytes, 3u * 16384u);
    // c's first use waits for a's last (sampled in the fragment shader of a_to_b).
    const BarrierBatch& beforeC = compiled.before[2];
    bool found = false;
    for (const ImageBarrier& bar : beforeC.images) {
        if (bar.resource != c.id) continue;
        found = true;
        EXPECT_EQ(bar.oldLayout, VK_IMAGE_LAYOUT_UNDEFINED);
        EXPECT_NE(bar.srcStages & VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, 0u);
    }
    EXPECT_TRUE(found);
}

TEST(FrameGraph, ErrorsNameThePasses) {
    {  // Two writers of one version.
        FrameGraph g;
        ResourceHandle r = g.importBuffer("lists", nullptr);
        g.addPass("first_writer", PassKind::Device, nullptr).write(r, Use::StorageWrite);
        g.addPass("second_writer", PassKind::Device, nullptr).write(r, Use::StorageWrite);
        const std::string error = compileError(g);
        EXPECT_NE(error.find("'first_writer'"), std::string::npos) << error;
        EXPECT_NE(error.find("'second_writer'"), std::string::npos) << error;
        EXPECT_NE(error.find("'lists'"), std::string::npos) << error;
        EXPECT_NE(error.find("undefined"), std::string::npos) << error;
    }
    {  // A transient read before anything wrote it.
        FrameGraph g;
        ResourceHandle r = g.createImage("gbuffer.normal", colorDesc());
        auto p = g.addPass("lighting", PassKind::Device, nullptr);
        p.read(r, Use::Sampled);
        p.sideEffect();
        const std::string error = compileError(g);
        EXPECT_NE(error.find("'lighting' reads 'gbuffer.normal' but no pass writes it"),
                  std::string::npos)
            << error;
    }
    {  // A version nobody produced.
        FrameGraph g;
        ResourceHandle r = g.importBuffer("ranges", nullptr);
        auto p = g.addPass("shade", PassKind::Device, nullptr);
        p.read({r.id, 3}, Use::StorageRead);
        p.sideEffect();
        EXPECT_NE(compileError(g).find("'shade' reads version 3 of 'ranges'"), std::string::npos);
    }
    {  // A cycle: each pass reads what the other writes (handles built by hand).
        FrameGraph g;
        ResourceHandle x = g.importBuffer("x", nullptr);
        ResourceHandle y = g.importBuffer("y", nullptr);
        auto a = g.addPass("pass_a", PassKind::Device, nullptr);
        a.read({x.id, 1}, Use::StorageRead);
        a.write(y, Use::StorageWrite);
        auto b = g.addPass("pass_b", PassKind::Device, nullptr);
        b.read({y.id, 1}, Use::StorageRead);
        b.write(x, Use::StorageWrite);
        const std::string error = compileError(g);
        EXPECT_NE(error.find("cycle"), std::string::npos) << error;
        EXPECT_NE(error.find("'pass_a'"), std::string::npos) << error;
        EXPECT_NE(error.find("'pass_b'"), std::string::npos) << error;
    }
}

TEST(FrameGraph, ShapeHashIgnoresImportedHandlesButNotUses) {
    auto build = [](const GpuBuffer* buffer, Use use) {
        FrameGraph g;
        ResourceHandle r = g.importBuffer("lists", buffer);
        g.addPass("p", PassKind::Device, nullptr).write(r, use);
        return g.shapeHash();
    };
    const GpuBuffer first, second;  // empty: only their addresses differ
    EXPECT_EQ(build(&first, Use::StorageWrite), build(&second, Use::StorageWrite));
    EXPECT_NE(build(&first, Use::StorageWrite), build(&first, Use::TransferDst));
}

TEST(TransientPlacement, NoTwoLiveResourcesShareBytes) {
    std::mt19937 rng(7);
    for (int trial = 0; trial < 200; ++trial) {
        std::vector<TransientInterval> intervals(1 + rng() % 12);
        for (TransientInterval& t : intervals) {
            t.size = 1 + rng() % 5000;
            t.alignment = uint64_t(1) << (rng() % 9);
            t.first = int32_t(rng() % 10);
            t.last = t.first + int32_t(rng() % 5);
        }
        const TransientPlacement p = placeTransients(intervals);
        uint64_t sum = 0;
        for (size_t i = 0; i < intervals.size(); ++i) {
            sum += intervals[i].size;
            EXPECT_EQ(p.offsets[i] % intervals[i].alignment, 0u);
            EXPECT_LE(p.offsets[i] + intervals[i].size, p.poolBytes);
            for (size_t j = 0; j < i; ++j) {
                const bool together = intervals[i].first <= intervals[j].last &&
                                      intervals[j].first <= intervals[i].last;
                const bool overlap = p.offsets[i] < p.offsets[j] + intervals[j].size &&
                                     p.offsets[j] < p.offsets[i] + intervals[i].size;
                EXPECT_FALSE(together && overlap) << "trial " << trial;
            }
        }
        EXPECT_LE(p.poolBytes, p.unaliasedBytes);
        EXPECT_GE(p.unaliasedBytes, sum);
    }
}

}  // namespace
}  // namespace candela::render
