// libFuzzer target: any bytes through the OpenEXR reader.
#include <cstddef>
#include <cstdint>

#include "candela/content/exr_image.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    candela::content::ExrLimits limits;
    limits.maxDimension = 4096;
    limits.maxTexels = 1u << 22;
    candela::content::Diagnostics diagnostics;
    (void)candela::content::readExrImageFromMemory({reinterpret_cast<const std::byte*>(data), size},
                                                   "fuzz.exr", diagnostics, limits);
    return 0;
}
