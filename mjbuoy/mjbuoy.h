// mjbuoy: buoyancy and hydrodynamics of floating bodies for MuJoCo 2.2.
//
// The sea and the hulls are described in the model's MJCF <custom> section
// (docs/mjcf.md). mjb_attach reads them, builds the hulls and installs an
// mjcb_passive callback; from then on every mj_step / mj_forward of that
// model adds one wrench per hull body to d->qfrc_passive. d->xfrc_applied is
// never written: it stays the user's.
//
// Units: SI (m, kg, s, N). Frames: world frame, z up. Angles in mjbuoy's
// MJCF entries and structs are degrees, whatever <compiler angle> says:
// MuJoCo passes <custom> data through unconverted (docs/mjcf.md).
//
// Threads: several mjData of one model may be stepped at once on different
// threads. mjbuoy's callbacks (mjcb_passive, mjcb_sensor) hold a model's
// lock shared for their whole run; mjb_setSea and mjb_detach take it
// exclusively, so they wait for callbacks of that model running on other
// threads, and no callback starts until they return. Called from inside a
// callback (mjbuoy's, or one it chains to) they would wait for themselves:
// they are refused instead (mjb_setSea returns 0 with the reason, mjb_detach
// warns and does nothing). mjb_bindData, mjb_copyData and mjb_unbindData of
// an mjData must not overlap a step of that same mjData; the read-only
// queries (mjb_wrench, mjb_notices, ...) of an mjData read what its last
// step left and belong on the thread that steps it.
#ifndef MJBUOY_MJBUOY_H_
#define MJBUOY_MJBUOY_H_

#include <mujoco/mujoco.h>

#include "mjbuoy_version.h"

// MJB_API marks the public C API: the shared library is built with hidden
// symbols and exports only what is declared with it. Start every function
// declared in this header with MJB_API (the test install.tree checks
// that libmjbuoy.so exports exactly the mjb_ functions declared here).
#ifndef MJB_API
#if defined(__GNUC__) || defined(__clang__)
#define MJB_API __attribute__((visibility("default")))
#else
#define MJB_API
#endif
#endif

#ifdef __cplusplus
extern "C" {
#endif

typedef struct mjbBuoy_ mjbBuoy;

// what an attached model holds
typedef struct mjbInfo_ {
  int nhull;             // hull geoms
  int nbody;             // bodies carrying at least one hull
  int ntri;              // hull triangles, all hulls
  int nvert;             // hull vertices, all hulls
  const char* backend;   // backend that runs: "cpu" or "gl"
  const char* renderer;  // device it runs on (CPU name or GL renderer)
} mjbInfo;

// check the mesh files an MJCF file names, before mj_loadXML reads it:
// MuJoCo 2.2 loads an OBJ face index out of range (reading past its vertex
// array) and non-finite vertices ("v nan 0 0") without a word, and its
// compiled mjModel keeps no file names, so mjb_attach cannot check them.
// Follows <include> and <compiler meshdir/assetdir>; checks every .obj (face
// indices in range and not 0, vertices finite) and binary .stl (size,
// vertices finite). Returns 1 if nothing is wrong (a missing or malformed
// file is left to MuJoCo's loader), else 0 with the file, line and fix in
// error (error_sz bytes). Every mjbuoy tool calls it before mj_loadXML.
// It also warns (mju_warning) when the model sets <compiler angle="radian">
// and has mjbuoy entries with angles, which are degrees regardless.
MJB_API int mjb_checkModelFile(const char* xmlpath, char* error, int error_sz);

// the same check of one .obj or .stl mesh file (other extensions: 1)
MJB_API int mjb_checkMeshFile(const char* path, char* error, int error_sz);

// attach mjbuoy to a compiled model. Reads and validates the "mjbuoy.*"
// custom entries, builds the hulls and installs the mjcb_passive callback
// (an mjcb_passive installed before is chained and still called).
// backend: NULL to use the model's mjbuoy.backend entry, else "cpu", "gl"
// or "auto" (gl when an EGL display with GL >= 4.3 is there, else cpu with
// a warning).
// Returns NULL on invalid input with the reason in error (error_sz bytes).
// The model must stay alive and unchanged until mjb_detach.
MJB_API mjbBuoy* mjb_attach(const mjModel* m, const char* backend, char* error, int error_sz);

// mjb_attach with radiation (and so diffraction and drift) off whatever
// the model's mjbuoy.radiation entries say; they are still checked. No
// panel solve and no cache read; the hulls take the drag defaults of a
// model without radiation (docs/physics.md section 16). For a look at the
// sea or the hulls that needs no hydrodynamic coefficients
// (mjbuoy-sim --print-sea); a model with radiation on moves differently
MJB_API mjbBuoy* mjb_attachWithoutRadiation(const mjModel* m, const char* backend, char* error,
                                            int error_sz);

// detach: stop adding forces to this model and free everything. The handle
// is invalid afterwards. mjb_detach(NULL), and a handle that is not attached
// (already detached) as long as no later mjb_attach returned the same
// address, are no-ops (the latter with an mju_warning).
// The callback chain: mjbuoy's one static mjcb_passive trampoline calls the
// callback it replaced first; a callback the user installs after mjb_attach
// may chain to it, also across detach and re-attach (docs/robustness.md).
// mjb_detach of the last model restores the callback it replaced if
// mjbuoy's trampoline is still installed.
MJB_API void mjb_detach(mjbBuoy* b);

// every model needs its own mjb_attach, copies from mj_copyModel included:
// a model with mjbuoy.* entries stepped without it gets no buoyancy and one
// mju_warning saying so

// per-mjData state is created on the first callback for d; call this right
// after mj_makeData to allocate it up front instead (0 on failure: out of
// memory; a failure in a callback gives d no force and one mju_warning).
// Its size is bounded at attach (docs/robustness.md, "State").
// The state knows its mjData by address plus a stamp: d->buffer, the
// fwdVelocity count d->timer[mjTIMER_VELOCITY].number at the last callback
// and d->time at the first callback of the last step. A new mjData at a recycled address, or d after
// mj_resetData, starts clean: zero wrench, no notices, no slamming history,
// no radiation memory (docs/physics.md section 14).
MJB_API int mjb_bindData(mjbBuoy* b, const mjData* d);

// copy mjbuoy's state for src (wrench, notices, slamming history,
// radiation memory) to dst;
// call right after mj_copyData(dst, m, src), which does not carry it, so
// that dst continues exactly like src (1 on success, 0 on failure)
MJB_API int mjb_copyData(mjbBuoy* b, mjData* dst, const mjData* src);

// finite-difference derivatives: mjd_transitionFD steps one mjData again
// and again from one state, and MuJoCo 2.2 does not put d->time back
// between (or after) those steps, so each would see the waves later and
// move mjbuoy's histories on (slamming, radiation memory, label guesses).
// Between mjb_freezeData(b, d, 1) and mjb_freezeData(b, d, 0) every
// callback for d computes from the state d had at the freeze, at the time
// it had then, and leaves that state as it was: each perturbed step gives
// what a fresh copy of d (mj_copyData + mjb_copyData) would. Unfreezing
// continues from that state; set d->time back yourself. cpu backend only
// (gl: 0). Returns 1, or 0 on failure. Usage:
//   double t = d->time;
//   mjb_freezeData(b, d, 1);
//   mjd_transitionFD(m, d, eps, centered, A, B, C, D);
//   mjb_freezeData(b, d, 0);
//   d->time = t;
MJB_API int mjb_freezeData(mjbBuoy* b, const mjData* d, int freeze);

// forget d's state; call before mj_deleteData if the process will keep
// stepping other mjData of the same model
MJB_API void mjb_unbindData(mjbBuoy* b, const mjData* d);

// the hull wrench mjbuoy added in the last callback for d: nbody x 6, laid
// out like xfrc_applied: world-frame force [N], then world-frame torque
// about the body's centre of mass d->xipos [N m]; the sum of the force
// families of mjb_wrenchPart (pressure, viscous, drag, slam, damping,
// wind). Zero for bodies without hulls or wind, and zero for a new or reset
// d before its first callback. NULL if d was never seen. Not in it (each
// reaches qfrc_passive on its own): the mooring lines' forces
// (mjb_lineWrench), radiation (added mass in qM, memory) and diffraction.
MJB_API const mjtNum* mjb_wrench(const mjbBuoy* b, const mjData* d);

// the force families that make up the wrench
typedef enum mjbPart_ {
  mjbPART_PRESSURE = 0,  // hydrostatic pressure (buoyancy), exact
  mjbPART_VISCOUS,       // viscous resistance (ITTC 1957)
  mjbPART_DRAG,          // pressure and suction drag
  mjbPART_SLAM,          // slamming
  mjbPART_DAMPING,       // simple linear damping
  mjbPART_WIND,          // wind: air drag and friction on dry faces (cpu, both backends)
  mjbNPART
} mjbPart;

// one force family's share of mjb_wrench, same layout; NULL if d was never
// seen or part is out of range
MJB_API const mjtNum* mjb_wrenchPart(const mjbBuoy* b, const mjData* d, int part);

// run-time notices for d, one line each, each fault reported once (a body
// whose state is not finite gets no force, and is named here; so is a force
// family that came out non-finite for a body, which is left out of its
// wrench); "" if none. Cleared when d is reset (mj_resetData), so later
// faults are reported
MJB_API const char* mjb_notices(const mjbBuoy* b, const mjData* d);

// sizes and backend of an attached model
MJB_API mjbInfo mjb_info(const mjbBuoy* b);

// radiation of an attached model (docs/physics.md section 14); all zero
// when it has none
typedef struct mjbRadInfo_ {
  int nbody;             // hull bodies with added mass and memory (0: radiation off)
  int nmode;             // state-space memory modes, all bodies (0: convolution memory)
  int nsample;           // convolution memory: samples of the longest kernel (0: state-space)
} mjbRadInfo;

// the radiation an attached model runs (NULL: all zero)
MJB_API mjbRadInfo mjb_radiationInfo(const mjbBuoy* b);

// before mjb_attach: how many hull bodies of m mjb_attach will give
// radiation, each a panel solve at attach (seconds to minutes) or a read
// of the radiation cache (docs/mjcf.md section 11); 0 for none, -1 when m
// is NULL or its mjbuoy.* entries are invalid (mjb_attach names the fault)
MJB_API int mjb_radiationBodies(const mjModel* m);

// gl backend: mean GPU time per call of each pipeline stage [ms], from GL
// timer queries; fills up to n names and times, returns the number of
// stages (0 for the cpu backend)
MJB_API int mjb_stageTimes(const mjbBuoy* b, const char** name, double* ms, int n);

// load-time warnings (open meshes, double-counted fluid forces, ...), one
// per line; empty string when there are none
MJB_API const char* mjb_warnings(const mjbBuoy* b);

// progress of long work inside mjb_attach, one line each (no newline), as
// it starts: per hull the panel solver solves, the body, its panels,
// frequencies, headings and the estimated time; per hull the radiation
// cache answers, the file read. Process-wide, for every later attach; fn
// is called on the attaching thread, one line at a time. NULL (the
// default) is silent. The tools print these lines on stderr
typedef void (*mjbProgress)(const char* line, void* user);
MJB_API void mjb_setProgress(mjbProgress fn, void* user);

// the exact sea surface height eta(x, y, t) [m] of an attached model
MJB_API mjtNum mjb_seaHeight(const mjbBuoy* b, mjtNum x, mjtNum y, mjtNum t);

// library version: 10000 major + 100 minor + patch (compare with
// MJBUOY_VERSION of the header compiled against), and as "major.minor.patch"
MJB_API int mjb_version(void);
MJB_API const char* mjb_versionString(void);

// ---- irregular seas and wind (docs/mjcf.md sections 8-10, docs/physics.md section 12) ----

// wave spectrum types
typedef enum mjbSpecType_ {
  mjbSPEC_PM = 0,        // Pierson-Moskowitz (from hs and tp, or from wind)
  mjbSPEC_JONSWAP,       // JONSWAP, DNV-RP-C205 normalisation
  mjbSPEC_TABLE          // tabulated (omega, S), linear in between, 0 outside
} mjbSpecType;

// one spectrum, expanded into n linear (Airy) components
typedef struct mjbSpectrum_ {
  int type;              // mjbSpecType
  double hs;             // significant wave height 4 sqrt(m0) [m] (PM, JONSWAP)
  double tp;             // peak period [s] (PM, JONSWAP)
  double wind;           // PM only: wind speed at 10 m [m/s] giving hs, tp; 0 = unused
  double gamma;          // JONSWAP peak enhancement [1, 10]
  const double* table;   // TABLE: ntable pairs (omega [rad/s], S [m^2 s/rad]), omega rising
  int ntable;            // TABLE: number of pairs (>= 2)
  double dir;            // mean direction of travel, from +x towards +y [deg]
  double spread;         // s of the spreading cos^2s((b - b0) / 2); 0 = long-crested
  int n;                 // number of components [1, 4096]
  double wmin, wmax;     // frequency range [rad/s]; both 0: 0.5 wp to 4 wp (table: its span)
  unsigned long long seed;  // random frequencies, phases and directions
} mjbSpectrum;

// defaults: JONSWAP, hs 1 m, tp 8 s, gamma 3.3, long-crested along +x,
// 64 components, default range, seed 1
MJB_API void mjb_defaultSpectrum(mjbSpectrum* s);

// gust spectra
typedef enum mjbGust_ {
  mjbGUST_NONE = 0,      // steady wind
  mjbGUST_FROYA          // Froya / API RP 2A-WSD spectrum of the speed at 10 m
} mjbGust;

// wind: mean speed and direction at 10 m, optional gusts
typedef struct mjbWind_ {
  double speed;          // 1-hour mean speed at 10 m above the still level [m/s]
  double dir;            // direction the wind blows towards, from +x towards +y [deg]
  int gust;              // mjbGust
  int ngust;             // gust components [1, 1024]
  unsigned long long seed;  // gust frequencies and phases
} mjbWind;

// a sea state for mjb_setSea
typedef struct mjbSea_ {
  double current[2];     // uniform current [m/s]
  const double* wave;    // nwave x 5, as mjbuoy.wave.<label>: amplitude [m],
  int nwave;             // wavelength [m], direction [deg], phase [deg], steepness Q
  const mjbSpectrum* spectrum;  // nspectrum spectra, added to the waves
  int nspectrum;
  mjbWind wind;
  double ramp;           // start-up ramp [s] from t = 0, as mjbuoy.sea.ramp (0 to 3600,
                         // 0 = off); negative keeps the model's
} mjbSea;

// replace the sea state of an attached model between steps: it waits for
// a callback of the model running on another thread, and is refused from
// inside a callback (threads, above); components, current and wind take
// effect in the next callback. Every value is checked against the ranges
// the model file's entries have (docs/mjcf.md), and each spectrum against
// the bounds of the sea it makes (Hs <= 50 m, Hs / Lp <= 1/7, no component
// shorter than 5 cm: docs/robustness.md).
// Density, level and depth stay the model's. Allocates nothing as long as
// the total component count stays within the capacity reserved at attach
// (the model's count, or mjbuoy.sea.capacity); more is an error. Returns 1,
// or 0 with the reason in error (the sea is then unchanged).
MJB_API int mjb_setSea(mjbBuoy* b, const mjbSea* sea, char* error, int error_sz);

// the current sea's components, 6 values each: amplitude [m], omega
// [rad/s], wave number k [rad/m], direction [deg], phase [deg], steepness
// Q; fills up to max components into out (may be NULL) and returns their
// total number
MJB_API int mjb_waves(const mjbBuoy* b, double* out, int max);

// wind speed vector at 10 m at time t [m/s] (mean plus gusts), 2 values
// (v NULL: nothing; b NULL: zero)
MJB_API void mjb_windVelocity(const mjbBuoy* b, mjtNum t, mjtNum v[2]);

// ---- mooring lines (docs/mooring.md) ----

// number of mooring lines of an attached model (its mjbuoy.line.<line>
// entries, in the order of their first entry)
MJB_API int mjb_lineCount(const mjbBuoy* b);

// node positions of line `line` in d, world frame [m], 3 values per node
// from the anchor (node 0) to the fairlead: fills up to max nodes into pos
// (may be NULL) and returns the line's node count, segments + 1. 0 when
// there is no such line or d has not been stepped
MJB_API int mjb_lineNodes(const mjbBuoy* b, const mjData* d, int line, mjtNum* pos, int max);

// segment tensions of line `line` in d [N], from the anchor's segment to
// the fairlead's, after its last step (at rest: its static equilibrium):
// fills up to max values into t (may be NULL) and returns the line's
// segment count. 0 when there is no such line or d has not been stepped
MJB_API int mjb_lineTensions(const mjbBuoy* b, const mjData* d, int line, mjtNum* t, int max);

// the wrench the mooring lines put on each body in the last callback for
// d: nbody x 6 like mjb_wrench (world-frame force [N], torque about xipos
// [N m]), the sum over the line ends on each body; zero for bodies with no
// line end, and NULL if the model has no lines or d was never seen. A
// body's total mjbuoy force is mjb_wrench plus this (plus radiation and
// diffraction when on)
MJB_API const mjtNum* mjb_lineWrench(const mjbBuoy* b, const mjData* d);

// the seabed of an attached model: 1 and its height z [m] (world frame)
// when it has one (a finite mjbuoy.sea.depth, or lines anchored on a fixed
// point or static body), else 0
MJB_API int mjb_seabed(const mjbBuoy* b, mjtNum* z);

#ifdef __cplusplus
}
#endif

#endif  // MJBUOY_MJBUOY_H_
