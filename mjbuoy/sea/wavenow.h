// wavenow: one wave component's constants at a fixed time (Sea::now); a
// header of its own with no inline code, so the per-instruction-set kernels
// (seavec_kern.h) can include it without sharing any function with the
// scalar path
#ifndef MJBUOY_WAVENOW_H_
#define MJBUOY_WAVENOW_H_

namespace mjb {

// per-call constants of one component at a fixed time t (Sea::now), so the
// hot loops do no per-wave setup; products keep label()'s association so a
// cold solve gives the same bits as label() + heightOf()
struct WaveNow {
  double k, dx, dy;  // wave number [rad/m], unit direction
  double wt, ph;     // omega t, phase [rad]
  double qx, qy;     // Q A dx, Q A dy [m]
  double qk;         // Q A k [1]
  double amp;        // A [m]
  double qao, ao;    // Q A omega, A omega [m/s]
  double aoo;        // A omega^2 [m/s^2]
};

}  // namespace mjb

#endif  // MJBUOY_WAVENOW_H_
