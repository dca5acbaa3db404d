// mjbuoy-scenario: a scenario file names a model, overrides its sea, sets
// initial states and lists checks on the simulated motion (docs/scenarios.md).
// This header holds the parsed scenario and the interfaces between the
// parts: parse (scenario_parse.cc), model editing and loading
// (scenario_model.cc), quantities and checks (scenario_checks.cc), the
// simulation loop (scenario_run.cc) and the report (scenario_report.cc).
#ifndef MJBUOY_TOOLS_SCENARIO_H_
#define MJBUOY_TOOLS_SCENARIO_H_

#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "mjbuoy.h"

namespace tinyxml2 { class XMLDocument; }

namespace scn {

constexpr double kInf = std::numeric_limits<double>::infinity();

// an invalid scenario: "FILE:LINE: reason" (exit status 2)
struct Invalid : std::runtime_error {
  Invalid(const std::string& file, int line, const std::string& why);
};

// an mjbuoy.* custom entry to set (data) or delete (remove)
struct Entry {
  std::string name;  // full name, e.g. mjbuoy.sea.density
  std::string data;
  bool text = false;    // <text> rather than <numeric>
  bool remove = false;  // delete the entry from the model
  int line = 0;
};

// <wave>: unset fields (NaN) keep the model's value for an existing wave
struct Wave {
  std::string name;  // label: the entry is mjbuoy.wave.<name>
  double amplitude, wavelength, direction, phase, steepness;  // NaN = unset
  int line = 0;
};

// <mesh name file>: replace an asset mesh's file (absolute path)
struct MeshFile {
  std::string name, file;
  int line = 0;
};

// <init>: initial state of a free body or of a hinge / slide joint
struct Init {
  std::string body, joint;
  bool has_pos = false, has_rpy = false, has_vel = false, has_angvel = false;
  bool has_qpos = false, has_qvel = false;
  double pos[3], rpy[3], vel[3], angvel[3];  // m, deg, m/s, deg/s (world frame)
  double qpos = 0, qvel = 0;                 // deg or m, deg/s or m/s
  int line = 0;
};

// what a quantity check measures per body and sample
// (SENSOR: a value of d->sensordata; its "body" is the sensordata address)
enum class Quantity { X, Y, Z, ROLL, PITCH, YAW, TILT, HEAVE, ETA, VX, VY, VZ,
                      FX, FY, FZ, TX, TY, TZ, FORCE, TORQUE, SENSOR };
enum class Kind { VALUE, RANGE, MEAN, STD, SETTLED, FINITE, ENERGY, WRENCH };
enum class Stat { VALUE, RANGE, MEAN, STD };

struct Check {
  Kind kind;
  std::string kind_name;  // as written: "range", "settled", ...
  std::string name;       // optional label given by the author
  std::string body_spec;  // body names or shell patterns, space separated
  std::vector<int> bodies;  // resolved against the model (sensor: its address)
  std::string sensor;       // sensor="NAME" instead of body and quantity
  int index = 0;            // value of a multi-dimensional sensor
  Quantity quantity = Quantity::Z;
  std::string quantity_name;
  int part = -1;  // mjbPART_* of the wrench, -1 = total
  std::string part_name;
  Stat stat = Stat::RANGE;
  double at = 0, from = 0, to = 0;  // to = duration if not given
  bool has_to = false;
  double lo = -kInf, hi = kInf;  // bounds on the measured value
  bool has_target = false;
  double target = 0, tol = 0;
  double maxqvel = 1000;  // finite: bound on |qvel| per dof
  int line = 0;
};

struct Scenario {
  std::string file;   // as given on the command line
  std::string name;   // suite name: name attribute or the file stem
  std::string model;  // resolved path of the model
  std::string model_attr;
  double duration = 0;
  double timestep = 0;  // 0: the model's
  std::string backend;  // "" = the model's mjbuoy.backend
  bool calm = false;    // delete the model's waves first
  std::vector<Entry> entries;
  std::vector<Wave> waves;
  std::vector<MeshFile> meshes;
  std::vector<Init> inits;
  std::vector<Check> checks;
  int line = 1;       // line of <scenario>
  int sea_line = 0;   // line of <sea>
};

// parse and validate a scenario file (throws Invalid)
Scenario parseScenario(const std::string& file);

// the same for XML text in memory; file names it in errors and is the
// directory that model and mesh paths are relative to (tests/fuzz)
Scenario parseScenarioText(const std::string& xml, const std::string& file);

// the same for a parsed document (mjbuoy-sweep edits it first; the elements
// keep their line numbers for errors)
Scenario parseScenarioDoc(const tinyxml2::XMLDocument& doc, const std::string& file);

// a quantity or wrench part by its name in a scenario file (false: unknown)
bool quantityByName(const std::string& name, Quantity* q);
bool partByName(const std::string& name, int* part);

// the model with the scenario applied, attached and initialised
struct Sim {
  mjModel* m = nullptr;
  mjData* d = nullptr;
  mjbBuoy* b = nullptr;
  std::string warnings;  // mjb_warnings
  Sim() = default;
  Sim(const Sim&) = delete;
  Sim& operator=(const Sim&) = delete;
  ~Sim();
};

// edit the model's MJCF (sea, waves, entries, meshes), compile it, attach
// mjbuoy, resolve the checks' bodies and apply <init> (throws Invalid).
// backend: "" for the scenario's / model's own
std::unique_ptr<Sim> loadScenario(Scenario& s, const std::string& backend);

// the MJCF text of the model with the scenario's edits (throws Invalid)
std::string editModel(const Scenario& s);

// one sample of the simulation: the state in d is that of time t
struct Sample {
  const mjModel* m;
  const mjData* d;
  const mjbBuoy* b;
  double t;
};

// the result of one check (or of the run itself)
struct Result {
  std::string label;    // e.g. "range barge.z over [20, 30] s"
  std::string kind;     // check kind, JUnit failure type
  bool pass = true;
  std::string detail;   // measured value and bound
};

// evaluates one check from the samples of the run
class Evaluator {
 public:
  virtual ~Evaluator() = default;
  virtual void sample(const Sample& s) = 0;
  // diverged: time the simulation stopped early, or +inf
  virtual Result finish(double diverged, const std::string& why) = 0;
};

// value of quantity q of body b in sample s (part: mjbPART_*, -1 = total;
// Quantity::SENSOR: b is the address in d->sensordata)
double quantityValue(const Sample& s, int b, Quantity q, int part);

// the d->sensordata address of value index of sensor name, or -1 with the
// reason in why (no such sensor, index out of range)
int sensorAddress(const mjModel* m, const std::string& name, int index, std::string* why);

std::unique_ptr<Evaluator> makeEvaluator(const Check& c, const mjModel* m, double dt);

// the label that names a check in the report
std::string checkLabel(const Check& c);

// units of a quantity ("m", "deg", "N", ...)
const char* quantityUnit(Quantity q);

// what a run produced
struct Report {
  std::string file, name;
  bool invalid = false;
  std::string error;  // invalid: FILE:LINE: reason
  std::string header;  // model, backend, sizes, times
  std::vector<Result> results;
  double wall = 0;  // s, load and run
  double diverged = kInf;  // time the simulation stopped early [s]
  bool passed() const;
};

// run the scenario and evaluate its checks; observe (if given) sees every
// sample too (mjbuoy-sweep's statistics)
void runScenario(const Scenario& s, Sim& sim, Report& r,
                 const std::function<void(const Sample&)>& observe = nullptr);

// print a report: one line per check, FAIL lines with the measurement
void printReport(const Report& r, FILE* out);

// write JUnit XML to f: one <testsuite> per scenario file (false on I/O
// error; the caller checks and closes f)
bool writeJUnit(const std::vector<Report>& reports, FILE* f);

// number formatting shared by the parts: %.6g, "inf" for infinities
std::string num(double v);

// the shortest decimal that reads back as v (scenario_parse.cc)
std::string exact(double v);

}  // namespace scn

#endif  // MJBUOY_TOOLS_SCENARIO_H_
