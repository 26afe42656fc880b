// tinygltf compiled from Debian's own header (libtinygltf-dev) into the fuzz target, with the same
// defaults as Debian's libtinygltf.so (nlohmann JSON, stb_image), so libFuzzer sees its branches
// and ASan/UBSan check its code. The executable's definitions take precedence over the shared
// library's, which fuzz_gltf still lists through st_scene; it is the same source, version 2.7.0.
// Only the fuzz target uses this: the shadowtune binary and the tests use libtinygltf.so.
#define TINYGLTF_IMPLEMENTATION
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <tiny_gltf.h>
