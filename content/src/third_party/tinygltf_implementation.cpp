// The one translation unit that compiles tinygltf. Image decoding is ours (image_decoding.cpp),
// so tinygltf's stb_image hookup and its glTF writer are left out.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#include <tiny_gltf.h>
