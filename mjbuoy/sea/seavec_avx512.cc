// the surface search over 8 points at once, AVX-512F (compiled with
// -mavx512f -mfma; called only when the cpu has them, vmath.cc)
#include <immintrin.h>

#include "sea/seavec_kern.h"
#include "sea/placekern.h"

// glibc libmvec, 8 doubles per call (x86_64 vector ABI, ISA "e" = AVX-512)
extern "C" __m512d _ZGVeN8v_sin(__m512d);
extern "C" __m512d _ZGVeN8v_cos(__m512d);
extern "C" __m512d _ZGVeN8v_exp(__m512d);

namespace mjb {
namespace {
struct Mvec8 {
  typedef Lanes<8>::V V;
  static V sin(V x) { return (V)_ZGVeN8v_sin((__m512d)x); }
  static V cos(V x) { return (V)_ZGVeN8v_cos((__m512d)x); }
  static V exp(V x) { return (V)_ZGVeN8v_exp((__m512d)x); }  // vExpAvx512's
};
}  // namespace

long solveLanesAvx512(const LaneIn& in) { return solveLanes<8, Mvec8>(in); }
int placeLanesAvx512(const PlaceIn& in) { return placeLanes<8>(in); }
int heightLanesAvx512(const HeightIn& in) { return heightLanes<8>(in); }
int packLanesAvx512(const PackIn& in) { return packLanes<8>(in); }
int wetLanesAvx512(const WetIn& in) { return wetLanes<8, Mvec8>(in); }
}  // namespace mjb
