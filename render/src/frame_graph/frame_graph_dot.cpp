// Graphviz of a compiled frame graph (candela run --frame-graph FILE.dot).
#include <sstream>

#include "frame_graph/frame_graph.h"

namespace candela::render {

namespace {
std::string escaped(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out;
}
}  // namespace

std::string frameGraphDot(const FrameGraph& graph, const CompiledFrameGraph& compiled) {
    std::ostringstream dot;
    dot << "digraph frame {\n  rankdir=LR;\n  node [fontname=\"Helvetica\", fontsize=10];\n"
        << "  edge [fontname=\"Helvetica\", fontsize=8];\n";
    const auto passes = graph.passes();
    const auto resources = graph.resources();
    std::vector<int32_t> position(passes.size(), -1);
    for (size_t i = 0; i < compiled.order.size(); ++i)
        position[compiled.order[i]] = int32_t(i);
    for (size_t p = 0; p < passes.size(); ++p) {
        dot << "  p" << p << " [shape=box, style=\"" << (compiled.culled[p] ? "dashed" : "filled")
            << "\", fillcolor=\"" << (passes[p].kind == PassKind::Host ? "#f6d8a8" : "#cfe2f3")
            << "\", label=\"";
        if (position[p] >= 0) dot << position[p] << ". ";
        dot << escaped(passes[p].name);
        if (passes[p].kind == PassKind::Host) dot << "\\n(host)";
        if (position[p] >= 0) {
            const size_t barriers = compiled.before[size_t(position[p])].count();
            if (barriers) dot << "\\n" << barriers << " barrier" << (barriers > 1 ? "s" : "");
        } else {
            dot << "\\n(culled)";
        }
        dot << "\"];\n";
    }
    for (size_t r = 0; r < resources.size(); ++r) {
        const ResourceDecl& res = resources[r];
        dot << "  r" << r << " [shape=" << (res.image ? "ellipse" : "note") << ", label=\""
            << escaped(res.name);
        if (!res.imported) {
            dot << "\\ntransient " << (compiled.poolSize[r] + 1023) / 1024 << " KiB at "
                << compiled.poolOffset[r] / 1024 << " KiB";
        } else {
            dot << "\\nimported";
        }
        dot << "\"];\n";
    }
    for (size_t p = 0; p < passes.size(); ++p) {
        for (const UseDecl& u : passes[p].uses) {
            const bool writes = useInfo(u.use, u.shaderStages).writes;
            if (writes) {
                dot << "  p" << p << " -> r" << u.resource;
            } else {
                dot << "  r" << u.resource << " -> p" << p;
            }
            dot << " [label=\"" << useName(u.use) << " v" << u.version + (writes ? 1 : 0)
                << "\"];\n";
        }
    }
    dot << "  end [shape=plaintext, label=\"end of frame\\n"
        << compiled.atEnd.count() << " barriers\"];\n}\n";
    return dot.str();
}

}  // namespace candela::render
