#include "frame_graph/frame_graph.h"

#include <algorithm>
#include <map>
#include <queue>
#include <span>
#include <utility>

#include "frame_graph/transient_placement.h"

namespace candela::render {

// ---- declaration ----------------------------------------------------------------------------

void FrameGraph::PassBuilder::read(ResourceHandle h, Use use, VkPipelineStageFlags2 stages) {
    graph_.passes_[pass_].uses.push_back({h.id, h.version, use, stages});
}

ResourceHandle FrameGraph::PassBuilder::write(ResourceHandle h, Use use,
                                              VkPipelineStageFlags2 stages) {
    graph_.passes_[pass_].uses.push_back({h.id, h.version, use, stages});
    return {h.id, h.version + 1};
}

void FrameGraph::PassBuilder::sideEffect() {
    graph_.passes_[pass_].sideEffect = true;
}

ResourceHandle FrameGraph::importImage(std::string name, const GpuImage* image, ImageState initial,
                                       ImageState final) {
    ResourceDecl r;
    r.name = std::move(name);
    r.imported = true;
    r.importedImage = image;
    if (image) r.imageDesc = image->desc();
    r.initial = initial;
    r.final = final;
    resources_.push_back(std::move(r));
    return {uint32_t(resources_.size() - 1), 0};
}

ResourceHandle FrameGraph::importBuffer(std::string name, const GpuBuffer* buffer,
                                        bool hostReadsAfterFrame) {
    ResourceDecl r;
    r.name = std::move(name);
    r.image = false;
    r.imported = true;
    r.importedBuffer = buffer;
    r.hostReadsAfterFrame = hostReadsAfterFrame;
    resources_.push_back(std::move(r));
    return {uint32_t(resources_.size() - 1), 0};
}

ResourceHandle FrameGraph::createImage(std::string name, const ImageDesc& desc) {
    ResourceDecl r;
    r.name = std::move(name);
    r.imageDesc = desc;
    resources_.push_back(std::move(r));
    return {uint32_t(resources_.size() - 1), 0};
}

ResourceHandle FrameGraph::createBuffer(std::string name, VkDeviceSize size,
                                        VkBufferUsageFlags usage) {
    ResourceDecl r;
    r.name = std::move(name);
    r.image = false;
    r.bufferSize = size;
    r.bufferUsage = usage;
    resources_.push_back(std::move(r));
    return {uint32_t(resources_.size() - 1), 0};
}

FrameGraph::PassBuilder FrameGraph::addPass(std::string name, PassKind kind,
                                            std::function<void(PassContext&)> execute) {
    PassDecl p;
    p.name = std::move(name);
    p.kind = kind;
    p.execute = std::move(execute);
    passes_.push_back(std::move(p));
    return PassBuilder(*this, uint32_t(passes_.size() - 1));
}

void FrameGraph::clear() {
    resources_.clear();
    passes_.clear();
}

uint64_t FrameGraph::shapeHash() const {
    // FNV-1a over everything compile() reads except imported handles.
    uint64_t h = 1469598103934665603ull;
    auto mix = [&h](const void* data, size_t bytes) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < bytes; ++i)
            h = (h ^ p[i]) * 1099511628211ull;
    };
    auto mixValue = [&mix](const auto& v) { mix(&v, sizeof(v)); };
    for (const ResourceDecl& r : resources_) {
        mix(r.name.data(), r.name.size());
        mixValue(r.image);
        mixValue(r.imported);
        mixValue(r.imageDesc.format);
        mixValue(r.imageDesc.width);
        mixValue(r.imageDesc.height);
        mixValue(r.imageDesc.mipLevels);
        mixValue(r.imageDesc.cube);
        mixValue(r.imageDesc.usage);
        mixValue(r.imageDesc.samples);
        mixValue(r.bufferSize);
        mixValue(r.bufferUsage);
        // Field by field: the structs have padding bytes.
        for (const ImageState& state : {r.initial, r.final}) {
            mixValue(state.layout);
            mixValue(state.stages);
            mixValue(state.access);
        }
        mixValue(r.hostReadsAfterFrame);
    }
    for (const PassDecl& p : passes_) {
        mix(p.name.data(), p.name.size());
        mixValue(p.kind);
        mixValue(p.sideEffect);
        for (const UseDecl& u : p.uses) {
            mixValue(u.resource);
            mixValue(u.version);
            mixValue(u.use);
            mixValue(u.shaderStages);
        }
    }
    return h;
}

// ---- compile --------------------------------------------------------------------------------

namespace {

std::string quoted(const std::string& s) {
    return "'" + s + "'";
}

// Only writes need making available; a read in a source scope is an execution dependency.
VkAccessFlags2 writeAccessOf(VkAccessFlags2 access) {
    return access &
           (VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT | VK_ACCESS_2_SHADER_WRITE_BIT |
            VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT |
            VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT |
            VK_ACCESS_2_HOST_WRITE_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT);
}

struct Edge {
    uint32_t from;
    uint32_t to;
    bool data;  // the consumer needs what the producer wrote (WAR edges only order)
};

// Names the passes of one cycle among `remaining` (passes Kahn's sort could not place).
std::string describeCycle(const FrameGraph& graph, const std::vector<std::vector<uint32_t>>& next,
                          const std::vector<bool>& remaining) {
    const uint32_t n = uint32_t(remaining.size());
    // Every remaining pass has a remaining predecessor; walk successors until one repeats.
    std::vector<int32_t> seenAt(n, -1);
    std::vector<uint32_t> path;
    uint32_t p = 0;
    while (p < n && !remaining[p])
        ++p;
    while (seenAt[p] < 0) {
        seenAt[p] = int32_t(path.size());
        path.push_back(p);
        uint32_t step = p;
        for (uint32_t s : next[p]) {
            if (remaining[s]) {
                step = s;
                break;
            }
        }
        if (step == p) break;
        p = step;
    }
    std::string text;
    for (size_t i = size_t(std::max(seenAt[p], 0)); i < path.size(); ++i) {
        text += quoted(graph.passes()[path[i]].name) + " -> ";
    }
    return text + quoted(graph.passes()[p].name);
}

// Who produced each version, and who reads it.
struct VersionIndex {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> producer;  // (resource, version) -> pass
    std::map<std::pair<uint32_t, uint32_t>, std::vector<uint32_t>> readers;
};

VersionIndex indexVersions(std::span<const PassDecl> passes,
                           std::span<const ResourceDecl> resources) {
    const uint32_t passCount = uint32_t(passes.size());
    VersionIndex index;
    for (uint32_t p = 0; p < passCount; ++p) {
        for (const UseDecl& u : passes[p].uses) {
            if (u.resource >= resources.size()) {
                throw FrameGraphError("frame graph: pass " + quoted(passes[p].name) +
                                      " uses a resource handle that was never declared");
            }
            const UseInfo info = useInfo(u.use, u.shaderStages);
            if (!info.writes) {
                index.readers[{u.resource, u.version}].push_back(p);
                continue;
            }
            auto [it, inserted] = index.producer.emplace(std::pair{u.resource, u.version + 1}, p);
            if (!inserted && it->second != p) {
                throw FrameGraphError(
                    "frame graph: passes " + quoted(passes[it->second].name) + " and " +
                    quoted(passes[p].name) + " both write version " + std::to_string(u.version) +
                    " of " + quoted(resources[u.resource].name) +
                    ", so their order is undefined (make one write the other's result)");
            }
        }
    }
    return index;
}

// Read after write (data edges from a version's producer to its readers) and write after read
// (order-only edges from a version's readers to the pass that overwrites it).
std::vector<Edge> dependencyEdges(std::span<const PassDecl> passes,
                                  std::span<const ResourceDecl> resources,
                                  const VersionIndex& index) {
    const uint32_t passCount = uint32_t(passes.size());
    std::vector<Edge> edges;
    for (uint32_t p = 0; p < passCount; ++p) {
        for (const UseDecl& u : passes[p].uses) {
            const ResourceDecl& r = resources[u.resource];
            const UseInfo info = useInfo(u.use, u.shaderStages);
            if (u.version > 0) {
                auto it = index.producer.find({u.resource, u.version});
                if (it == index.producer.end()) {
                    throw FrameGraphError("frame graph: pass " + quoted(passes[p].name) +
                                          " reads version " + std::to_string(u.version) + " of " +
                                          quoted(r.name) + " but no pass writes it");
                }
                if (it->second != p) edges.push_back({it->second, p, true});
            } else if (!r.imported && info.reads && !info.writes) {
                throw FrameGraphError("frame graph: pass " + quoted(passes[p].name) + " reads " +
                                      quoted(r.name) + " but no pass writes it");
            }
            if (info.writes) {
                // Write after read: the readers of the version this pass overwrites go first.
                auto it = index.readers.find({u.resource, u.version});
                if (it == index.readers.end()) continue;
                for (uint32_t q : it->second) {
                    if (q != p) edges.push_back({q, p, false});
                }
            }
        }
    }
    return edges;
}

// Culling: keep passes with side effects or writes to imported resources, then whatever
// produced what a kept pass reads.
std::vector<bool> livePasses(std::span<const PassDecl> passes,
                             std::span<const ResourceDecl> resources, std::span<const Edge> edges) {
    const uint32_t passCount = uint32_t(passes.size());
    std::vector<bool> live(passCount, false);
    std::vector<std::vector<uint32_t>> producersOf(passCount);
    for (const Edge& e : edges) {
        if (e.data) producersOf[e.to].push_back(e.from);
    }
    std::vector<uint32_t> stack;
    for (uint32_t p = 0; p < passCount; ++p) {
        bool root = passes[p].sideEffect;
        for (const UseDecl& u : passes[p].uses) {
            root |= resources[u.resource].imported && useInfo(u.use, u.shaderStages).writes;
        }
        if (root) {
            live[p] = true;
            stack.push_back(p);
        }
    }
    while (!stack.empty()) {
        const uint32_t p = stack.back();
        stack.pop_back();
        for (uint32_t q : producersOf[p]) {
            if (!live[q]) {
                live[q] = true;
                stack.push_back(q);
            }
        }
    }
    return live;
}

// Order: Kahn's algorithm over the live passes, ties broken by declaration order.
std::vector<uint32_t> orderLivePasses(const FrameGraph& graph, std::span<const Edge> edges,
                                      const std::vector<bool>& live) {
    const uint32_t passCount = uint32_t(live.size());
    std::vector<std::vector<uint32_t>> next(passCount);
    std::vector<uint32_t> inDegree(passCount, 0);
    for (const Edge& e : edges) {
        if (!live[e.from] || !live[e.to]) continue;
        next[e.from].push_back(e.to);
        ++inDegree[e.to];
    }
    std::priority_queue<uint32_t, std::vector<uint32_t>, std::greater<>> ready;
    for (uint32_t p = 0; p < passCount; ++p) {
        if (live[p] && inDegree[p] == 0) ready.push(p);
    }
    std::vector<uint32_t> order;
    while (!ready.empty()) {
        const uint32_t p = ready.top();
        ready.pop();
        order.push_back(p);
        for (uint32_t s : next[p]) {
            if (--inDegree[s] == 0) ready.push(s);
        }
    }
    const size_t liveCount = size_t(std::count(live.begin(), live.end(), true));
    if (order.size() != liveCount) {
        std::vector<bool> remaining(passCount, false);
        for (uint32_t p = 0; p < passCount; ++p)
            remaining[p] = live[p] && inDegree[p] > 0;
        throw FrameGraphError("frame graph: cycle between passes " +
                              describeCycle(graph, next, remaining));
    }
    return order;
}

std::vector<ResourceLifetime> resourceLifetimes(std::span<const PassDecl> passes,
                                                std::span<const uint32_t> order,
                                                size_t resourceCount) {
    std::vector<ResourceLifetime> lifetimes(resourceCount);
    for (size_t i = 0; i < order.size(); ++i) {
        for (const UseDecl& u : passes[order[i]].uses) {
            ResourceLifetime& l = lifetimes[u.resource];
            if (l.first < 0) l.first = int32_t(i);
            l.last = int32_t(i);
        }
    }
    return lifetimes;
}

// The transients the frame uses, in declaration order, with their lifetimes and placement.
struct Transients {
    std::vector<uint32_t> resources;
    std::vector<TransientInterval> intervals;  // per entry of `resources`
    TransientPlacement placement;
};

// Transient placement in one pool of the memory types every transient accepts.
Transients placeTransientResources(std::span<const ResourceDecl> resources,
                                   CompiledFrameGraph& out) {
    Transients t;
    for (uint32_t r = 0; r < resources.size(); ++r) {
        if (resources[r].imported || out.lifetimes[r].first < 0) continue;
        t.resources.push_back(r);
        const MemoryNeeds& needs = resources[r].needs;
        t.intervals.push_back({needs.size, std::max<VkDeviceSize>(needs.alignment, 1),
                               out.lifetimes[r].first, out.lifetimes[r].last});
        out.poolMemoryTypeBits &= needs.memoryTypeBits;
    }
    t.placement = placeTransients(t.intervals);
    out.poolOffset.assign(resources.size(), 0);
    out.poolSize.assign(resources.size(), 0);
    for (uint32_t r : t.resources)
        out.poolSize[r] = resources[r].needs.size;
    for (size_t i = 0; i < t.resources.size(); ++i)
        out.poolOffset[t.resources[i]] = t.placement.offsets[i];
    out.poolBytes = t.placement.poolBytes;
    out.unaliasedBytes = t.placement.unaliasedBytes;
    return t;
}

// A resource's state during the barrier walk.
struct ResourceState {
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkPipelineStageFlags2 writeStages = 0;  // last write (or layout transition)
    VkAccessFlags2 writeAccess = 0;
    VkPipelineStageFlags2 readStages = 0;     // reads since then
    VkPipelineStageFlags2 visibleStages = 0;  // made visible to since the last write
    VkAccessFlags2 visibleAccess = 0;
};

// Imported resources start in their declared state, transients in none.
std::vector<ResourceState> initialStates(std::span<const ResourceDecl> resources) {
    std::vector<ResourceState> state(resources.size());
    for (uint32_t r = 0; r < resources.size(); ++r) {
        if (resources[r].imported) {
            state[r].layout = resources[r].initial.layout;
            state[r].writeStages = resources[r].initial.stages;
            state[r].writeAccess = resources[r].initial.access;
        }
    }
    return state;
}

// A transient that reuses another's bytes waits for that one's last use.
void waitForAliasedTransients(std::vector<ResourceState>& state, std::span<const PassDecl> passes,
                              std::span<const uint32_t> order, const Transients& transients) {
    const std::vector<uint64_t>& offsets = transients.placement.offsets;
    for (size_t i = 0; i < transients.resources.size(); ++i) {
        for (size_t j = 0; j < transients.resources.size(); ++j) {
            const TransientInterval& a = transients.intervals[i];
            const TransientInterval& b = transients.intervals[j];
            const bool sharesBytes =
                offsets[i] < offsets[j] + b.size && offsets[j] < offsets[i] + a.size;
            if (i == j || !sharesBytes || b.last >= a.first) continue;
            for (const UseDecl& u : passes[order[size_t(b.last)]].uses) {
                if (u.resource != transients.resources[j]) continue;
                const UseInfo info = useInfo(u.use, u.shaderStages);
                state[transients.resources[i]].writeStages |= info.stages;
                state[transients.resources[i]].writeAccess |= writeAccessOf(info.access);
            }
        }
    }
}

void addMemory(BarrierBatch& b, VkPipelineStageFlags2 srcStages, VkAccessFlags2 srcAccess,
               VkPipelineStageFlags2 dstStages, VkAccessFlags2 dstAccess) {
    b.memorySrcStages |= srcStages;
    b.memorySrcAccess |= writeAccessOf(srcAccess);
    b.memoryDstStages |= dstStages;
    b.memoryDstAccess |= dstAccess;
}

// Moves image `r` from its state `s` to `newLayout`, waiting for every use since the last
// write and making that write available.
ImageBarrier layoutTransition(uint32_t r, const ResourceState& s, VkImageLayout newLayout,
                              VkPipelineStageFlags2 dstStages, VkAccessFlags2 dstAccess) {
    ImageBarrier b;
    b.resource = r;
    b.oldLayout = s.layout;
    b.newLayout = newLayout;
    b.srcStages = s.writeStages | s.readStages;
    b.srcAccess = writeAccessOf(s.writeAccess);
    b.dstStages = dstStages;
    b.dstAccess = dstAccess;
    return b;
}

// Merge a pass's uses of one resource (e.g. sampled and storage read in one pass).
std::map<uint32_t, UseInfo> mergeUses(const PassDecl& pass,
                                      std::span<const ResourceDecl> resources) {
    std::map<uint32_t, UseInfo> merged;
    for (const UseDecl& u : pass.uses) {
        const UseInfo info = useInfo(u.use, u.shaderStages);
        auto [it, inserted] = merged.emplace(u.resource, info);
        if (inserted) continue;
        it->second.stages |= info.stages;
        it->second.access |= info.access;
        it->second.writes |= info.writes;
        it->second.reads |= info.reads;
        // Buffers have no layout: a uniform and a storage read of one buffer may share a pass.
        if (resources[u.resource].image && it->second.layout != info.layout) {
            throw FrameGraphError("frame graph: pass " + quoted(pass.name) + " uses " +
                                  quoted(resources[u.resource].name) +
                                  " in two image layouts at once");
        }
    }
    return merged;
}

// Adds to `batch` what resource `r` (in state `s`) needs before `use`, and updates `s`.
void synchronizeUse(BarrierBatch& batch, ResourceState& s, uint32_t r, bool image,
                    const UseInfo& use) {
    const bool layoutChange = image && s.layout != use.layout;
    if (layoutChange) {
        batch.images.push_back(layoutTransition(r, s, use.layout, use.stages, use.access));
        s.layout = use.layout;
        // The transition is a write made visible to this use; a writing use's own
        // writes are visible to nobody yet.
        s.writeStages = use.stages;
        s.writeAccess = writeAccessOf(use.access);
        s.readStages = use.writes ? 0 : use.stages;
        s.visibleStages = use.writes ? 0 : use.stages;
        s.visibleAccess = use.writes ? 0 : use.access;
        return;
    }
    if (use.writes) {
        // Write after write / read: wait for both; make the earlier writes available.
        if (s.writeStages | s.readStages) {
            addMemory(batch, s.writeStages | s.readStages, s.writeAccess, use.stages, use.access);
        }
        s.writeStages = use.stages;
        s.writeAccess = writeAccessOf(use.access);
        s.readStages = 0;
        s.visibleStages = 0;  // until a barrier makes these writes visible
        s.visibleAccess = 0;
        return;
    }
    const bool visible =
        (use.stages & ~s.visibleStages) == 0 && (use.access & ~s.visibleAccess) == 0;
    if (!visible && (s.writeStages != 0)) {
        addMemory(batch, s.writeStages, s.writeAccess, use.stages, use.access);
        s.visibleStages |= use.stages;
        s.visibleAccess |= use.access;
    }
    s.readStages |= use.stages;
}

// Barriers: walk the passes in order with each resource's state.
void computePassBarriers(std::span<const PassDecl> passes, std::span<const ResourceDecl> resources,
                         std::vector<ResourceState>& state, CompiledFrameGraph& out) {
    out.before.resize(out.order.size());
    for (size_t i = 0; i < out.order.size(); ++i) {
        BarrierBatch& batch = out.before[i];
        const PassDecl& pass = passes[out.order[i]];
        for (const auto& [r, use] : mergeUses(pass, resources))
            synchronizeUse(batch, state[r], r, resources[r].image, use);
        out.barrierCount += batch.count();
    }
}

// After the last pass: host reads of imported buffers, imported images to their final state.
void computeEndOfFrameBarriers(std::span<const ResourceDecl> resources,
                               std::span<const ResourceState> state, CompiledFrameGraph& out) {
    for (uint32_t r = 0; r < resources.size(); ++r) {
        const ResourceDecl& decl = resources[r];
        if (decl.hostReadsAfterFrame && state[r].writeAccess) {
            addMemory(out.atEnd, state[r].writeStages, state[r].writeAccess,
                      VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
        }
        if (!decl.imported || !decl.image || decl.final.layout == VK_IMAGE_LAYOUT_UNDEFINED)
            continue;
        const ResourceState& s = state[r];
        if (s.layout == decl.final.layout && s.writeStages == 0) continue;
        out.atEnd.images.push_back(
            layoutTransition(r, s, decl.final.layout, decl.final.stages, decl.final.access));
    }
    out.barrierCount += out.atEnd.count();
}

}  // namespace

CompiledFrameGraph compileFrameGraph(const FrameGraph& graph) {
    const auto passes = graph.passes();
    const auto resources = graph.resources();
    const uint32_t passCount = uint32_t(passes.size());
    CompiledFrameGraph out;

    const VersionIndex versions = indexVersions(passes, resources);
    const std::vector<Edge> edges = dependencyEdges(passes, resources, versions);

    const std::vector<bool> live = livePasses(passes, resources, edges);
    out.culled.resize(passCount);
    for (uint32_t p = 0; p < passCount; ++p)
        out.culled[p] = !live[p];

    out.order = orderLivePasses(graph, edges, live);
    out.lifetimes = resourceLifetimes(passes, out.order, resources.size());
    const Transients transients = placeTransientResources(resources, out);

    std::vector<ResourceState> state = initialStates(resources);
    waitForAliasedTransients(state, passes, out.order, transients);
    computePassBarriers(passes, resources, state, out);
    computeEndOfFrameBarriers(resources, state, out);
    return out;
}

}  // namespace candela::render
