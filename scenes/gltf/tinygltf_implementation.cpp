// tinygltf's code, compiled once here (Debian's README.Debian, second route) rather than
// linked from libtinygltf.so: without stb_image (TINYGLTF_NO_STB_IMAGE, _WRITE), so that
// every image goes through the project's own reader (gltf_document.cpp's image callback),
// with Debian's nlohmann json the project already uses (tiny_gltf.h includes it), and instrumented with the rest of
// the reader in the sanitizer and fuzzer builds.
// (TINYGLTF_NO_STB_IMAGE and _WRITE are the library's compile definitions,
// scenes/CMakeLists.txt, since they change the class every includer sees.)
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
