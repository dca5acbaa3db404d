// the surface search over 4 points at once, AVX2 + FMA (compiled with
// -mavx2 -mfma; called only when the cpu has them, vmath.cc)
#include <immintrin.h>

#include "sea/seavec_kern.h"
#include "sea/placekern.h"

// glibc libmvec, 4 doubles per call (x86_64 vector ABI, ISA "d" = AVX2)
extern "C" __m256d _ZGVdN4v_sin(__m256d);
extern "C" __m256d _ZGVdN4v_cos(__m256d);
extern "C" __m256d _ZGVdN4v_exp(__m256d);

namespace mjb {
namespace {
struct Mvec4 {
  typedef Lanes<4>::V V;
  static V sin(V x) { return (V)_ZGVdN4v_sin((__m256d)x); }
  static V cos(V x) { return (V)_ZGVdN4v_cos((__m256d)x); }
  static V exp(V x) { return (V)_ZGVdN4v_exp((__m256d)x); }  // vExpAvx2's
};
}  // namespace

long solveLanesAvx2(const LaneIn& in) { return solveLanes<4, Mvec4>(in); }
int placeLanesAvx2(const PlaceIn& in) { return placeLanes<4>(in); }
int heightLanesAvx2(const HeightIn& in) { return heightLanes<4>(in); }
int packLanesAvx2(const PackIn& in) { return packLanes<4>(in); }
int wetLanesAvx2(const WetIn& in) { return wetLanes<4, Mvec4>(in); }
}  // namespace mjb
