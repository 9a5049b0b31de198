#pragma once
// The quarter-mask test of light assignment, four quarters at once: which of a cluster's four
// quarter boxes (common/light_list_entry.h) the light's bounding shape reaches. The same answer
// as boundingShapeTouchesBoxes(bounds, quarterBoxes, 4, padPerDepth), bit for bit: the SSE
// path does its arithmetic operation for operation, and the shortcut below is exact. Why: the
// scalar loop of four box tests was a third of what the masks added to the CPU assignment.
#include <cstdint>

#include "clustered/light_bounds.h"

namespace candela::render {

// quarterBoxes: CLUSTER_QUARTER_BOXES_FLOATS floats (per quarter min xyz, max xyz; min x >
// max x when the quarter has no pixel). Returns bit q for each quarter reached. Call it only
// for a light whose test on the cluster's box (the quarters' union), padded the same way,
// passed: with a single occupied quarter that box is the quarter's, bit for bit, so spheres and
// cones (whose two tests are the same) need no quarter test.
uint32_t quarterBoxesTouched(const LightBounds& bounds, const float* quarterBoxes,
                             float padPerDepth);

}  // namespace candela::render
