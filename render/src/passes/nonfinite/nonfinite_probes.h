#pragma once
// A diagnosis frame's probes: after every device pass that writes a float colour image, a pass
// that counts that image's non-finite texels into a slot of its own (NonFinitePass). Read in
// execution order, the first probe with a count names the pass a NaN or Inf came from.
// Only a frame after one whose radiance was not finite pays for them.
#include <cstdint>
#include <string>
#include <vector>

#include "frame_graph/frame_graph.h"

namespace candela::render {

class NonFinitePass;

struct NonFiniteProbe {
    uint32_t slot = 0;        // NonFinitePass slot its count goes to
    uint32_t writerPass = 0;  // declaration index of the pass it probes
    std::string passName;
    std::string imageName;
};

// Whether a pass's write of this image can be probed: a 2D float colour image with one
// sample, not a cube (the probe samples it as a sampler2D).
bool probeableImage(const ImageDesc& desc);

// Adds the probes to `graph` (before compiling); probed transients gain SAMPLED usage.
// Imported images without it are left out. `firstSlot`: slots below it are taken.
std::vector<NonFiniteProbe> addNonFiniteProbes(FrameGraph& graph, const NonFinitePass& pass,
                                               uint32_t firstSlot, uint32_t slotCount);

// The probe whose writer ran first among those with a count (counts: per probe, in the
// order addNonFiniteProbes returned them; executionOrder: the compiled order of declaration
// indices), or null when none counted anything.
const NonFiniteProbe* firstNonFiniteProbe(const std::vector<NonFiniteProbe>& probes,
                                          const std::vector<uint32_t>& counts,
                                          const std::vector<uint32_t>& executionOrder);

}  // namespace candela::render
