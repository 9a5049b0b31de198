// A clustered light list entry, shared by the GLSL that reads it and the C++ that writes it
// (valid in both languages): the light's index in the low 28 bits and, in the top 4, which
// quarters of the cluster's screen tile the light reaches. Bit LIGHT_ENTRY_QUARTER_SHIFT + q is
// quarter q = (right half) + 2 * (lower half) of the tile (quarterOfPixel in clusters.glsl);
// a pixel evaluates only the entries with its quarter's bit set. Directional lights, which
// lead the index buffer, are plain indices.
#ifndef CANDELA_LIGHT_LIST_ENTRY_H
#define CANDELA_LIGHT_LIST_ENTRY_H

#define LIGHT_ENTRY_INDEX_MASK 0x0FFFFFFFu
#define LIGHT_ENTRY_QUARTER_SHIFT 28u
#define LIGHT_ENTRY_ALL_QUARTERS 0xF0000000u
// The boxes the masks come from, in the cluster-bounds buffer: first, for every cluster, min
// xyz then max xyz of its pixels in view space (CLUSTER_BOX_FLOATS; the union of its quarters,
// dense, as the per-cluster test reads it), then for every cluster the same per quarter
// (CLUSTER_QUARTER_BOXES_FLOATS at clusterCount * CLUSTER_BOX_FLOATS + cluster * 24; a quarter
// without pixels has min > max, kEmptyQuarterBound). Written for occupied clusters only.
#define CLUSTER_BOX_FLOATS 6u
#define CLUSTER_QUARTER_BOXES_FLOATS 24u
#define CLUSTER_BOUNDS_FLOATS (CLUSTER_BOX_FLOATS + CLUSTER_QUARTER_BOXES_FLOATS)

#endif
