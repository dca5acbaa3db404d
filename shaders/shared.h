// shared.h: buffer layouts, binding points and workgroup sizes shared by
// the C++ side and the GLSL compute shaders. Defined here once, used twice:
// C++ does #include "shared.h" (namespace mjb::glsl); a shader's line
// #include "shared.h" is replaced by this file when cmake/embed_shaders.cmake
// embeds it. Rules, so both compilers read the same bytes the same way:
// - write only the common subset of C++ and GLSL: #define, #ifdef, and
//   struct NAME { TYPE member; ... }; with TYPE float, int, uint, vec2, vec4,
//   ivec4 or another struct from here, and fixed-size arrays of them
// - no vec3 (std430 aligns it to 16 bytes but sizes it 12), no bool (4 bytes
//   in GLSL, 1 in C++), no double (optional in GLSL 4.3), no mat*
// - these structs go in std430 buffers only (std140 pads differently);
//   order members by alignment and pad by hand to a multiple of the largest
//   member's alignment, so C++ sizeof equals the std430 array stride
// - every struct gets a static_assert on its size in the C++ block at the end
// - C++-only lines go inside #ifdef __cplusplus (GLSL never defines it)
#ifndef MJBUOY_SHADERS_SHARED_H_
#define MJBUOY_SHADERS_SHARED_H_

#ifdef __cplusplus
#include <cstdint>
namespace mjb {
namespace glsl {
typedef uint32_t uint;
struct alignas(8) vec2 { float x, y; };
struct alignas(16) vec4 { float x, y, z, w; };
struct alignas(16) ivec4 { int x, y, z, w; };
#endif

// self test (shaders/selftest.comp): y = a x + b per item, then per-segment
// sums of y over uneven segments, the pattern of the per-body wrench sums
#define SELFTEST_LOCAL 64     // workgroup size of both stages
#define SELFTEST_ITEMS 0      // SSBO binding of SelftestItem[]
#define SELFTEST_SEGMENTS 1   // SSBO binding of SelftestSegment[]

struct SelftestItem {
  float x;
  float a;
  float b;
  float y;     // output: a x + b
};

struct SelftestSegment {
  int start;   // first item
  int count;   // items, any number >= 0
  float sum;   // output: sum of y over the segment
  uint pad;
};

#ifdef __cplusplus
static_assert(sizeof(SelftestItem) == 16, "std430 stride of SelftestItem");
static_assert(sizeof(SelftestSegment) == 16, "std430 stride of SelftestSegment");
}  // namespace glsl
}  // namespace mjb
#endif

#endif  // MJBUOY_SHADERS_SHARED_H_
