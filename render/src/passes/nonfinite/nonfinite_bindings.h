#ifndef CANDELA_NONFINITE_BINDINGS_H
#define CANDELA_NONFINITE_BINDINGS_H
// Descriptor bindings of nonfinite_count.comp, shared with nonfinite_pass.cpp.
#define NONFINITE_BINDING_IMAGE 0
#define NONFINITE_BINDING_COUNTS 1
#endif
