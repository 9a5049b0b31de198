// The one translation unit that compiles stb_vorbis (Ogg Vorbis clips, decoded from memory).
#define STB_VORBIS_NO_STDIO
#define STB_VORBIS_NO_PUSHDATA_API
#include <stb_vorbis.h>
