#pragma once
// stb_vorbis (libstb-dev) declarations, configured as its implementation TU compiles it
// (third_party/stb_vorbis_implementation.cpp): decoding from memory only.
#define STB_VORBIS_NO_STDIO
#define STB_VORBIS_NO_PUSHDATA_API
#define STB_VORBIS_HEADER_ONLY
#include <stb_vorbis.h>
