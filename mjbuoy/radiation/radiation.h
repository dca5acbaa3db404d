// radiation in the time domain (docs/physics.md section 14): Cummins'
// equation for a hull body from its frequency-domain HydroCoef. The
// infinite-frequency added mass joins MuJoCo's inertia matrix (implicit),
// its Kirchhoff velocity terms and the radiation memory are forces
#ifndef MJBUOY_RADIATION_H_
#define MJBUOY_RADIATION_H_

#include <memory>
#include <string>
#include <vector>

#include "util/pool.h"

#include <mujoco/mujoco.h>

#include "radiation/hydrocoef.h"
#include "mjbuoy.h"
#include "radiation/radfit.h"

namespace mjb {

struct State;

// one body with radiation, set up by setRadiation
struct RadBody {
  int body;                  // MuJoCo body id
  double ref[3];             // reference point in the body frame [m]
  double A[36];              // A_inf about ref, body axes, row-major
  std::vector<int> dof;      // dofs that move the body, leaf to root
  std::vector<int> pair;     // (i, j) = 6 i + j with a retardation function
  std::vector<double> K;     // K_pair(k dt), pair-major, nk each [N/m, ...];
                             // empty for a twin (copyMemory), which has only Kr
  // each pair's K in reverse (oldest sample's weight first), what the
  // convolution reads; shared by bodies with the same memory (one copy of a
  // fleet's kernels stays in cache)
  std::shared_ptr<const std::vector<double>> Kr;
  int nk = 0;                // memory samples (0: no memory)
  SsModes ss;                // state-space memory (radfit.h); empty: the convolution
  int soff = 0;              // its first mode in RadState's ssX, ssPw
  // immersion (docs/physics.md, "Immersion factor"): the hull bodies of
  // the rigid group, whose pressure force gives the displaced volume now,
  // and the volume at the pose of the panel solution [m^3]; veq 0: the
  // coefficients are not scaled (setHydroCoef, a group without hulls)
  std::vector<int> hb;
  double veq = 0;
  // viscous roll damping about the body's x axis, linear [N m s/rad] and
  // quadratic [N m s^2/rad^2]: Radiation::roll (the user's), plus at
  // attach the rollzeta share of critical, 2 zeta sqrt(C44 (I44 + A44));
  // c44: the hydrostatic roll stiffness about the group's COM [N m/rad]
  // (<= 0: no roll restoring, no rollzeta share;
  // radattach.cc, docs/physics.md section 14, "Viscous roll damping")
  double roll[2] = {0, 0};
  double c44 = 0;
  // forward speed (radspeed.h): L_22 then L_33, nls samples each at dt
  // [N s/m]; empty: no speed terms (off, or no memory)
  std::vector<double> Ls;
  int nls = 0;
  // what K and ss were computed from: memory length asked [s], step [s],
  // frequencies and B; a later body with the same key copies them
  std::vector<double> key;
};

// the radiation coupling of two bodies solved together (mjbuoy.radiation.group;
// docs/physics.md section 14, "Interaction"): the force on body i (rb
// index) from the motion of body j, -A_ij(inf) a_j - int K_ij(t - s) nu_j(s) ds,
// about each body's ref in its body axes at attach, A_ij(inf) from the
// last step's acceleration (separate trees share no entry of MuJoCo's qM)
struct RadCouple {
  int i = 0, j = 0;
  double A[36];              // A_ij(inf), row-major (force dof of i, motion dof of j)
  std::vector<int> pair;     // (a, b) = 6 a + b with a kernel
  std::vector<double> K;     // K_pair(k dt) reversed (oldest first), pair-major, nk each
  int nk = 0;
};

// all bodies of one attached model
struct Radiation {
  std::vector<RadBody> rb;
  std::vector<RadCouple> cp;  // couplings of grouped bodies; nch: their ring's length (>= 2)
  int nch = 2;
  double dt = 0;             // step of the memory samples [s] (opt.timestep at set time)
  int maxdof = 0;            // longest dof chain
  int nh = 1;                // history ring length: the longest convolution memory
                             // (2 for state-space bodies), >= 1
  std::vector<int> simple0;  // m->dof_simplenum before the first body was set
  bool conv = false;         // mjbuoy.radiation.memorymodel = convolution: no fit
  bool ssAsked = false;      // statespace given explicitly: a fallback is noted
  // the user's viscous roll damping about each body's x axis, linear
  // [N m s/rad] and quadratic [N m s^2/rad^2] (mjbuoy.radiation.rolldamping):
  // each RadBody's roll starts from it (setRadiation)
  double roll[2] = {0, 0};
  // the water's momentum taken up as the immersion factor rises
  // (mjbuoy.radiation.entry; docs/physics.md section 14, "Water entry")
  bool entry = false;
  // Salvesen-Tuck-Faltinsen's forward-speed memory terms (mjbuoy.radiation.speed;
  // docs/physics.md section 14, "Forward speed"): 0 off, 1 hulls slender along x
  // (A11_inf <= kSlenderA11 A22_inf), 2 every body; and their ring's length (>= 1)
  int speed = 1;
  int nsh = 1;
  int nmode = 0;             // state-space modes of all bodies
  std::vector<std::string> note;  // fits that fell back to the convolution (when ssAsked)
};

// rb's memory wrench f (body frame, 6) from hist, each dof's ring of nh
// body-frame velocities with the newest at head and count samples held:
// f = -dt sum_k w_k K(k dt) nu(t - k dt), trapezoid weights w over the
// samples held (radstep.cc; docs/physics.md section 14)
void radMemory(const RadBody& rb, const double* hist, int nh, int head, int count, double dt,
               double* f);

// per mjData: velocity history and the memory force of the current step
struct RadState {
  std::vector<double> hist;  // per body and dof a ring of nh body-frame velocities at ref
  std::vector<double> fmem;  // per body 6: memory wrench of this step (body frame)
  std::vector<double> jac;   // scratch: 6 x maxdof body-frame Jacobian columns
  std::vector<double> ajac;  // scratch: A_inf times each column
  std::vector<char> told;    // per body: a non-finite force was named
  std::vector<cplx> ssX, ssPw;  // per mode: state-space sums (SsState)
  // per mode: exp(p h) at the timestep h = ssDt in force when it is not
  // Radiation::dt, the step of attach (opt.timestep changed since);
  // dtTold: that change was noted
  std::vector<cplx> ssLam;
  double ssDt = 0;
  bool dtTold = false;
  std::vector<double> ssNu;  // per body 12: first and newest velocity samples
  std::vector<double> imm;   // per body: immersion factor of this call, in [0, 1]
  std::vector<double> sstep; // per body 2: immersion factor at the last step's time, this step's
  int head = 0, count = 0;   // newest sample, samples held
  // per body 2 rings of nsh: the wetted sway and heave velocities (body axes, at ref)
  // the forward-speed terms of a convolution body read (radspeed.h; a state-space
  // body's come from its modes' states); their newest sample and count
  std::vector<double> shist;
  int shead = 0, scount = 0;
  long key = -1;             // mjTIMER_STEP count at the last call (-1: none)
  double tcur = 0;           // time of the current step [s]
  long mstamp = -1;          // mjTIMER_POSITION count whose qM holds A_inf
  // per body: qM's diagonal at its first dof once A_inf was added there;
  // with mstamp it tells a qM that holds A_inf from one mj_crb rebuilt
  // (mj_resetData then mj_forward gives the same counts again)
  std::vector<double> mdiag;
  // the convolution's parts of this step that do not read the newest
  // sample, 3 per pair (radstep.cc pairParts), computed before the per-body
  // loop, on the cpu backend's threads when there is enough of it; poff:
  // each body's first pair
  std::vector<double> pre;
  std::vector<int> poff;
  // couplings (RadCouple): per body a ring of nch wetted body-frame
  // velocities at ref, its newest sample and count; per couple its wrench
  // on body i (body frame) of this step
  std::vector<double> chist, fcp;
  int chead = 0, ccount = 0;
};

// K_ij(k dt), k = 0..n-1, from B_ij of c: K(t) = (2/pi) int_0^inf B cos(w t) dw
// with B linear between the table's frequencies, linear from 0 at w = 0 to
// the first and, beyond the last, the power-law tail of radtail.h (tail
// false: zero there; docs/physics.md section 14, "High-frequency tail")
void retardation(const HydroCoef& c, int i, int j, double dt, int n, double* K,
                 bool tail = true);

// the same with the tail exponents p of tailExponents(c, p) given (nullptr:
// no tail), for callers that build several pairs of one c: the exponents'
// fit is done once, not once per pair
void retardationP(const HydroCoef& c, const double* p, int i, int j, double dt, int n, double* K);

// a hull is slender along x, as strip theory's forward-speed terms assume,
// when A11_inf <= kSlenderA11 A22_inf: a prolate spheroid of length over
// beam 2.5 or more (Lamb 1932, "Hydrodynamics", sec. 373: k1 0.21, k2 0.70
// at 2; k1 0.12, k2 0.80 at 3)
const double kSlenderA11 = 0.2;

// K over n samples tapered to zero over its last quarter, less the
// sin^2 that makes its trapezoid sum 0 (docs/physics.md section 14, "Steady gain")
void steadyZero(double* K, int n);

// memory length [s] for c when none is given: the time after which every
// |K_ij| stays below 1% of the largest |K| (at most kMaxMemory)
double memoryLength(const HydroCoef& c);
// the frequency-domain memory length [s] (docs/physics.md section 14,
// "Memory length"): the shortest of T_0 g^k (T_0 = memoryLength(c), g =
// kMemoryGrowth) at which the transform of each pair's K, cut there,
// tapered and made zero-gain (steadyZero), reproduces B_ij at the table's
// frequencies within kMemoryTol of the pair's scale, at most
// kAutoMemoryMax (or T_0 if longer). *worst (if given) gets the worst
// pair's error there (a fraction of its scale), *pair its 6 i + j
double memoryLengthByTransform(const HydroCoef& c, double* worst = nullptr, int* pair = nullptr);
const double kMaxMemory = 60;
const double kMemoryTol = 0.03;    // of the pair's scale sqrt(S_i S_j), S_d = peak |B_dd|
const double kAutoMemoryMax = 30;  // [s] the automatic length's cap
const double kMemoryGrowth = 1.2;  // ratio of successive lengths tried

// the most samples a retardation function keeps per pair: a convolution
// memory longer than this many timesteps is refused with its cost; a
// state-space memory samples its kernel at a coarser step for the fit
// (whose modes are continuous in time) instead (docs/physics.md section
// 14, "Small timesteps")
const int kMaxKernelSamples = 1 << 17;
// the samples of a kernel resampled for the state-space fit
const int kFitKernelSamples = 8192;

// true when A (6 x 6, row-major) is finite but not positive semi-definite
// within round-off: the water it carries would have negative kinetic energy
bool addedMassIndefinite(const double A[36]);

// add radiation to body of an attached model (replacing what it had):
// c's A_inf, and its memory over tmem seconds (0: memoryLength(c); <0: no
// memory). Checks c and body; "" or the error. Changes m->dof_simplenum of
// the body's dofs (MuJoCo's diagonal-inertia shortcut: added mass couples
// them); restoreModel puts it back
std::string setRadiation(const mjModel* m, int body, const HydroCoef& c, double tmem,
                         Radiation* r);
void restoreModel(const mjModel* m, const Radiation& r);

// add the coupling of rb index i (force) and j (motion) from c, whose A, B
// and Ainf hold the 6x6 block (i, j) about the bodies' refs in their body
// axes: K from B by retardation (no high-frequency tail: the block changes
// sign), over tmem seconds (0: memoryLength). "" or the error
std::string setCouple(int i, int j, const HydroCoef& c, double tmem, double dt, Radiation* r);

// size s's radiation state for r; clear its history
void radMakeState(const Radiation& r, RadState* s);
void radRestart(RadState* s);

struct Sea;

// the immersion factor's knee: s = clamp(V / (kImmKnee V_eq), 0, 1) is 1
// while the hulls keep at least this share of their displacement at the
// panel solution's pose (docs/physics.md, "Immersion factor")
const double kImmKnee = 0.5;

// each body's immersion factor into s->imm from the pressure stage's
// world force (part: the mjbPART_PRESSURE family, 6 per MuJoCo body;
// bad[b], badp[np b]: body b's state or pressure was not finite, which
// finishWrench names: the last factor is kept),
// V = F_z / (rho g): the displaced volume below the water surface
// (exact on flat water); O(hull bodies), no allocation
void radImmersion(const Radiation& r, const double* part, const char* bad, const char* badp,
                  int np, double rhog, RadState* s);

// in mjcb_passive: add each body's A_inf to d->qM (refactored) and its
// Kirchhoff and memory forces to d->qfrc_passive, each scaled by the
// body's immersion factor s->imm (radImmersion; the memory's history
// holds s nu, the velocity of the wetted surface). The memory acts on the
// velocity relative to the sea's uniform current, the Kirchhoff terms on
// the velocity relative to the water at the body's COM (current and wave
// orbital velocity; docs/physics.md section 14, "Kirchhoff terms in waves")
// pool: the cpu backend's workers (nullptr: none), which share the
// memory convolutions' pairs when they are long enough to repay it; the
// result does not depend on it
void radiationStep(const Radiation& r, const mjModel* m, mjData* d, RadState* s, const Sea& sea,
                   std::string* notices, Pool* pool = nullptr);

// give body (a MuJoCo body id) of an attached model radiation from c, with
// a memory of tmem seconds (0: automatic, memoryLength; < 0: none). Call
// between steps; every mjData's radiation history restarts. "" or the
// error. Its viscous roll damping is mjbuoy.radiation.rolldamping alone:
// without panels there is no C44 for a rollzeta share (radattach.cc adds
// that for the groups it solves). (Internal API for now: the panel solver
// feeds it at attach.)
std::string setHydroCoef(mjbBuoy* b, int body, const HydroCoef& c, double tmem = 0);

}  // namespace mjb

#endif  // MJBUOY_RADIATION_H_
