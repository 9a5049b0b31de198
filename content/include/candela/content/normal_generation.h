#pragma once
// Flat normals for primitives that have none, as glTF requires ("client implementations MUST
// calculate flat normals"): every triangle gets its own three vertices and face normal.
#include "candela/content/model.h"

namespace candela::content {

// Unwelds `primitive` (indices become 0..3n-1, every stream is expanded) and fills normals.
// Degenerate triangles get +Y. Sets normalsGenerated.
void generateFlatNormals(Primitive& primitive);

}  // namespace candela::content
