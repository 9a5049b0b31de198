#pragma once
// A pass that copies one image whole (mip 0, layer 0) over another of the same format and size:
// the resolves that cannot write the image they read (TAA, GBAA) write a transient, and this
// puts it back so the passes after them read the resolved frame under its old name.
#include "frame_graph/frame_graph.h"

namespace candela::render {

// Declares the copy of `source` (read as TransferSrc) over `target` (written as TransferDst);
// returns target's new version.
ResourceHandle declareImageCopy(FrameGraph& graph, const char* name, ResourceHandle source,
                                ResourceHandle target);

}  // namespace candela::render
