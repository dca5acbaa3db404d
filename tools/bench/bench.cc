// mjbuoy-bench: the dissertation's grid (boats x Wigley resolutions on a
// Gerstner sea), timing mjbuoy's forces, the full mj_step and a bare mj_step
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <sstream>
#include <string>
#include <ctime>
#include <filesystem>
#include <system_error>
#include <unistd.h>
#include <vector>

#include <CLI/CLI.hpp>

#include <mujoco/mujoco.h>

#include "benchcmp.h"
#include "benchscene.h"
#include "cliopt.h"
#include "guard.h"
#include "modelload.h"
#include "mjbuoy.h"  // and mjbuoy_version.h
#include "outfile.h"
#include "roofline.h"
#include "api/buoy.h"  // internal: mjb::newtonStats
#include "radiation/radiation.h"  // internal: mjb::setHydroCoef until MJCF switches exist

using Clock = std::chrono::steady_clock;

// boats spaced on a grid 6 m x 2 m apart, all partly wet on a 20 m swell
static int gthreads = -1;  // mjbuoy.threads, -1: leave it out (auto)
static std::string gsea = "swell";  // flat, swell (one Gerstner wave), jonswap, longcrested
static double gradiation = -1;  // --radiation: memory length [s]; < 0: off
static std::string gradmem;     // --radiation-memory: mjbuoy.radiation.memorymodel, "": default
static bool gwarmmem = false;   // --warm-memory: warm up until every radiation memory is full
static double gseriestol = 0;  // --seriestol: mjbuoy.sea.seriestol, 0: left out (exact)
static std::string ginteg;  // --integration: mjbuoy.sea.integration, "": left out (exact)
static bool gradoff = false;    // --radiation-off: mjbuoy.radiation off (on by default)

// --radiation: every boat gets synthetic coefficients of the Wigley's
// size (docs/physics.md section 14): A_inf on the diagonal, and B of each
// dof plus the surge-pitch coupling of the causal form 2 k0 a w^2 /
// (a^2 + w^2)^2 (60 frequencies 0.1 to 20 rad/s), memory gradiation s.
// What is measured is the cost, not these numbers
static bool addRadiation(mjbBuoy* b, const mjModel* m) {
  const double M[6] = {176.2, 176.2, 176.2, 6.02, 237.28, 238.6};
  const double share[6] = {0.05, 0.5, 1.0, 0.2, 1.0, 0.5}, a = 4;
  mjb::HydroCoef c;
  for (int i = 0; i < 6; i++) c.Ainf[7 * i] = share[i] * M[i];
  for (double w = 0.1; w <= 20; w *= std::pow(200.0, 1 / 59.0)) {
    c.omega.push_back(w);
    for (int k = 0; k < 36; k++) {
      int i = k / 6, j = k % 6;
      double k0 = i == j ? a * a * c.Ainf[k] : (i + j == 4 && i != j ? 0.1 * a * a * 176.2 : 0);
      c.B.push_back(2 * k0 * a * w * w / std::pow(a * a + w * w, 2));
    }
  }
  for (int bd = 1; bd < m->nbody; bd++) {
    std::string e = mjb::setHydroCoef(b, bd, c, gradiation > 0 ? gradiation : -1);
    if (!e.empty()) {
      std::fprintf(stderr, "mjbuoy-bench: %s\n", e.c_str());
      return false;
    }
  }
  // a memory fit that fell back to the convolution says so here
  std::fputs(mjb_warnings(b), stderr);
  return true;
}
static std::string gpress = "linear";  // mjbuoy.sea.pressure: linear or kerner
static int glines = 0;     // --lines: mooring lines per boat
static int gsegments = 20;  // --segments: segments per line

// --lines: n mooring lines per boat at equal angles, each gsegments
// segments of a 20 mm polyester rope (0.5 kg/m; EA 1.2 MN, about 20 times
// its breaking load of 60 kN; submerged weight 1.8 N/m, so the boat sinks
// by a few kg of line), 20 m long from a
// fairlead at the boat's origin to an anchor 15 m out on a bed 10 m down:
// a catenary with about a third of it on the bed (docs/benchmarks.md
// "Mooring lines")
static std::string lineEntries(int boats) {
  if (glines <= 0) return "";
  std::ostringstream s;
  s << "<numeric name=\"mjbuoy.linetype.rope.mass\" data=\"0.5\"/>"
    << "<numeric name=\"mjbuoy.linetype.rope.diameter\" data=\"0.02\"/>"
    << "<numeric name=\"mjbuoy.linetype.rope.ea\" data=\"1.2e6\"/>";
  int side = std::ceil(std::sqrt(boats));
  for (int i = 0; i < boats; i++) {
    for (int k = 0; k < glines; k++) {
      const double a = 2 * M_PI * k / glines;
      const std::string n = "mjbuoy.line.b" + std::to_string(i) + "_" + std::to_string(k);
      s << "<text name=\"" << n << ".type\" data=\"rope\"/>"
        << "<numeric name=\"" << n << ".length\" data=\"20\"/>"
        << "<numeric name=\"" << n << ".segments\" data=\"" << gsegments << "\"/>"
        << "<numeric name=\"" << n << ".anchor\" data=\"" << 6 * (i % side) + 15 * std::cos(a)
        << " " << 2 * (i / side) + 15 * std::sin(a) << " -10\"/>"
        << "<text name=\"" << n << ".fairlead\" data=\"f" << i << "\"/>";
    }
  }
  return s.str();
}

// the sea entries of --sea: jonswap is a 64-component short-crested sea
// (Hs 0.6 m, Tp 5 s, spreading s = 10 about 20 deg), longcrested the same
// spectrum with every component along 20 deg (spreading 0, the default)
static std::string seaEntries() {
  if (gsea == "flat") return "";
  if (gsea == "swell") return "<numeric name=\"mjbuoy.wave.swell\" data=\"0.3 20 20 0 0.5\"/>";
  return std::string("<text name=\"mjbuoy.spectrum.sea.type\" data=\"jonswap\"/>"
                     "<numeric name=\"mjbuoy.spectrum.sea.hs\" data=\"0.6\"/>"
                     "<numeric name=\"mjbuoy.spectrum.sea.tp\" data=\"5\"/>"
                     "<numeric name=\"mjbuoy.spectrum.sea.components\" data=\"64\"/>"
                     "<numeric name=\"mjbuoy.spectrum.sea.direction\" data=\"20\"/>") +
         (gsea == "jonswap" ? "<numeric name=\"mjbuoy.spectrum.sea.spreading\" data=\"10\"/>" : "");
}

static std::string scene(const std::string& meshes, int boats, int tris) {
  std::ostringstream s;
  s << "<mujoco><option timestep=\"0.002\"/><asset><mesh name=\"w\" file=\"" << meshes
    << "/wigley_" << tris << ".obj\"/></asset><custom>"
    << "<text name=\"mjbuoy.hulls\" data=\"h*\"/>"
    << seaEntries() << "<text name=\"mjbuoy.sea.pressure\" data=\"" << gpress << "\"/>";
  if (gthreads >= 0) s << "<numeric name=\"mjbuoy.threads\" data=\"" << gthreads << "\"/>";
  if (!gradmem.empty()) s << "<text name=\"mjbuoy.radiation.memorymodel\" data=\"" << gradmem << "\"/>";
  if (gradoff) s << "<text name=\"mjbuoy.radiation\" data=\"off\"/>";
  if (gseriestol > 0) {
    s << "<numeric name=\"mjbuoy.sea.seriestol\" data=\"" << gseriestol << "\"/>";
  }
  if (!ginteg.empty()) s << "<text name=\"mjbuoy.sea.integration\" data=\"" << ginteg << "\"/>";
  s << lineEntries(boats) << "</custom><worldbody>";
  int side = std::ceil(std::sqrt(boats));
  for (int i = 0; i < boats; i++) {
    s << "<body pos=\"" << 6 * (i % side) << " " << 2 * (i / side) << " 0.03\"><freejoint/>"
      << "<inertial pos=\"0 0 -0.08\" mass=\"176.2\" diaginertia=\"6.02 237.28 238.6\"/>"
      << "<geom name=\"h" << i << "\" type=\"mesh\" mesh=\"w\" contype=\"0\" conaffinity=\"0\"/>";
    if (glines > 0) s << "<site name=\"f" << i << "\"/>";
    s << "</body>";
  }
  s << "</worldbody></mujoco>";
  return s.str();
}

static mjModel* compile(const std::string& xml) {
  mjVFS vfs;
  mj_defaultVFS(&vfs);
  mj_makeEmptyFileVFS(&vfs, "bench.xml", xml.size());
  std::copy(xml.begin(), xml.end(), (char*)vfs.filedata[mj_findFileVFS(&vfs, "bench.xml")]);
  char err[512];
  mjModel* m = mj_loadXML("bench.xml", &vfs, err, sizeof(err));
  mj_deleteVFS(&vfs);
  if (!m) std::fprintf(stderr, "mjbuoy-bench: %s\n", err);
  return m;
}

// the callback mjbuoy installed, timed
static mjfGeneric ginner = nullptr;
static double ghydro = 0, gcpu = 0;
// CPU time of all the process's threads (llvmpipe's too) [s]: unlike wall
// time, it barely moves when other processes load the machine
static double cpuTime() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}
static void timed(const mjModel* m, mjData* d) {
  double c0 = cpuTime();
  auto t0 = Clock::now();
  ginner(m, d);
  ghydro += std::chrono::duration<double>(Clock::now() - t0).count();
  gcpu += cpuTime() - c0;
}

struct Cell {
  int boats, tris, ntri;
  std::string backend, sea, pressure;
  int lines;  // mooring lines per boat
  double hydro, step, bare;  // ms per step (median of repetitions)
  double cpu;                // CPU ms (all threads) in mjbuoy per step (median)
  double newton;             // cpu backend: Newton steps per surface solve (NaN: none)
  double vertex;             // cpu backend: ms per step in the vertex stage, all threads
  std::vector<std::pair<std::string, double>> stages;
};

// the reference kernel's CPU ns per triangle on a sea (roofline.h), once
// per sea: components of flat 0, swell 1, jonswap and longcrested 64
static double roofline(const std::string& sea) {
  static double ns[3] = {-1, -1, -1};
  const int i = sea == "flat" ? 0 : sea == "swell" ? 1 : 2;
  if (ns[i] < 0) ns[i] = mjbtool::rooflineNs(i == 0 ? 0 : i == 1 ? 1 : 64);
  return ns[i];
}

// a cell's fraction of the roofline: the kernel's time for its triangles
// over mjbuoy's CPU time (all threads) per step
static double fraction(const std::string& sea, int ntri, double cpuMs) {
  return roofline(sea) * ntri / (cpuMs * 1e6);
}

static double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

static bool run(const std::string& meshes, int boats, int tris, const std::string& be,
                int steps, int reps, Cell* c) {
  mjModel* m = compile(scene(meshes, boats, tris));
  if (!m) return false;
  mjData* d = mj_makeData(m);
  // bare step first, then with mjbuoy
  std::vector<double> bare, full, hydro, cpu;
  for (int r = 0; r < reps; r++) {
    mj_resetData(m, d);
    auto t0 = Clock::now();
    for (int i = 0; i < steps; i++) mj_step(m, d);
    bare.push_back(std::chrono::duration<double>(Clock::now() - t0).count() * 1e3 / steps);
  }
  char err[512];
  mjbBuoy* b = mjb_attach(m, be.c_str(), err, sizeof(err));
  if (!b) {
    std::fprintf(stderr, "mjbuoy-bench: %s\n", err);
    mj_deleteData(d);
    mj_deleteModel(m);
    return false;
  }
  if (gradiation >= 0 && !addRadiation(b, m)) {
    mjb_detach(b);
    mj_deleteData(d);
    mj_deleteModel(m);
    return false;
  }
  mjb_bindData(b, d);
  std::string why;  // mj_resetData below clears the bare runs' warnings
  ginner = mjcb_passive;
  mjcb_passive = timed;
  mj_resetData(m, d);
  // warm up; with --radiation until the memory's history is full, the
  // convolution's steady cost
  int warm = 5 + (gradiation > 0 ? int(std::ceil(gradiation / m->opt.timestep)) : 0);
  // the memory the attach computed (radiation on by default): its history
  // fills after nh steps, and the convolution's cost grows until then
  if (gwarmmem) warm = std::max(warm, 5 + mjb::buoyOf(b)->rad.nh);
  for (int i = 0; i < warm; i++) mj_step(m, d);
  long ns0 = 0, ni0 = 0, ns1 = 0, ni1 = 0;
  mjb::newtonStats(b, d, &ns0, &ni0);
  double vs0 = 0, vs1 = 0;
  mjb::vertexSeconds(b, d, &vs0);
  for (int r = 0; r < reps; r++) {
    ghydro = gcpu = 0;
    auto t0 = Clock::now();
    for (int i = 0; i < steps; i++) mj_step(m, d);
    full.push_back(std::chrono::duration<double>(Clock::now() - t0).count() * 1e3 / steps);
    hydro.push_back(ghydro * 1e3 / steps);
    cpu.push_back(gcpu * 1e3 / steps);
    // a diverging cell is no measurement: MuJoCo reset it and timed the reset state
    if (mjbtool::diverged(d, &why)) break;
  }
  mjcb_passive = ginner;
  mjb::newtonStats(b, d, &ns1, &ni1);
  mjb::vertexSeconds(b, d, &vs1);
  if (!why.empty()) {
    std::fprintf(stderr, "mjbuoy-bench: %d boats x %d triangles on %s diverged: %s\n", boats,
                 tris, be.c_str(), why.c_str());
    mjb_unbindData(b, d);
    mj_deleteData(d);
    mjb_detach(b);
    mj_deleteModel(m);
    return false;
  }
  const char* sn[8];
  double ms[8];
  int ns = mjb_stageTimes(b, sn, ms, 8);
  *c = Cell{boats, tris, mjb_info(b).ntri, mjb_info(b).backend, gsea, gpress, glines, median(hydro),
            median(full), median(bare), median(cpu),
            ns1 > ns0 ? double(ni1 - ni0) / (ns1 - ns0) : NAN,
            vs1 > vs0 ? (vs1 - vs0) * 1e3 / (double(steps) * reps) : NAN, {}};
  for (int i = 0; i < ns; i++) c->stages.emplace_back(sn[i], ms[i]);
  mjb_unbindData(b, d);
  mj_deleteData(d);
  mjb_detach(b);
  mj_deleteModel(m);
  return true;
}

// dissertation (Cruz 2023), GTX 1660 Ti GPU ms per frame: physics.md section 5
static double paper(int boats, int tris) {
  const int B[] = {1, 50, 100, 200, 400, 800}, T[] = {64, 256, 576, 7744};
  const double v[6][4] = {{0.999, 0.904, 1.01, 8.46},   {4.86, 5.43, 6.49, 17.07},
                          {9.88, 10.86, 13.12, 34.77}, {19.38, 21.72, 26.12, 69.47},
                          {38.66, 43.72, 52.19, 138.57}, {76.1, 86.87, 103.62, 278.83}};
  for (int i = 0; i < 6; i++) {
    for (int j = 0; j < 4; j++) {
      if (B[i] == boats && T[j] == tris) return v[i][j];
    }
  }
  return NAN;
}

// what each cell measures in turn: the sea, the pressure model, the mooring
// lines per boat
struct Kind {
  std::string sea, pressure;
  int lines;
};

// one cell of --baseline: this bench and the baseline's, each as a child
// process running the cell once (--reps 1), alternating A/B reps times
struct CmpCell {
  std::string backend, sea, pressure;
  int boats, tris;
  int lines = 0;
  double hydro = 0, bhydro = 0, ratio = 0, step = 0, bstep = 0, sratio = 0;
  double cpu = 0, bcpu = 0, cratio = 0;  // CPU time of all threads in mjbuoy
  int ntri = 0;
  double newton = NAN, bnewton = NAN;
  double vertex = NAN, bvertex = NAN, vratio = NAN;  // vertex stage ms (cpu backend)
};

static bool compareCell(const std::string& self, const std::string& base,
                        const std::vector<std::string>& common, const std::string& dir,
                        int reps, CmpCell* c) {
  std::vector<double> ha, hb, sa, sb, rh, rs, ca, cb, rc, va, vb, rv;
  mjbtool::CmpRun a, b;
  for (int r = 0; r < reps; r++) {
    std::string e;
    if (!mjbtool::benchChild(self, common, dir, &a, &e) ||
        !mjbtool::benchChild(base, common, dir, &b, &e)) {
      std::fprintf(stderr, "mjbuoy-bench: --baseline: %s\n", e.c_str());
      return false;
    }
    ha.push_back(a.hydro);
    hb.push_back(b.hydro);
    sa.push_back(a.step);
    sb.push_back(b.step);
    rh.push_back(b.hydro / a.hydro);
    rs.push_back(b.step / a.step);
    ca.push_back(a.cpu);
    cb.push_back(b.cpu);
    rc.push_back(b.cpu / a.cpu);
    va.push_back(a.vertex);
    vb.push_back(b.vertex);
    rv.push_back(b.vertex / a.vertex);
  }
  c->vertex = median(va);
  c->bvertex = median(vb);
  c->vratio = median(rv);
  c->cpu = median(ca);
  c->bcpu = median(cb);
  c->cratio = median(rc);
  c->hydro = median(ha);
  c->bhydro = median(hb);
  c->step = median(sa);
  c->bstep = median(sb);
  c->ratio = median(rh);  // of the pairs: each pair ran back to back
  c->sratio = median(rs);
  c->ntri = a.ntri;
  c->newton = a.newton;
  c->bnewton = b.newton;
  return true;
}

static std::string num(double v, const char* fmt) {
  if (!std::isfinite(v)) return "";
  char s[64];
  std::snprintf(s, sizeof(s), fmt, v);
  return s;
}

// --baseline: every cell of the grid run by both builds, side by side
static int compareGrid(const std::string& base, const std::string& meshes,
                       const std::vector<int>& tris, const std::vector<int>& boats,
                       const std::vector<std::string>& backends,
                       const std::vector<Kind>& kinds,
                       int steps, int reps, std::vector<CmpCell>* out) {
  // the children's JSON and stderr: a private directory (benchscene.h)
  std::string self, tmp;
  if (!mjbtool::baselineSetup(&self, &tmp)) return 1;
  const char* exe = self.c_str();
  const char* dir = tmp.c_str();
  // a lines column only when some cell is moored (--lines): the unmoored
  // table keeps its columns
  bool anyLines = false;
  for (const Kind& k : kinds) anyLines |= k.lines > 0;
  std::printf("| backend | sea | pressure | boats | tris/boat | hydro ms | baseline hydro ms | "
              "baseline/this hydro | hydro CPU ms | baseline hydro CPU ms | baseline/this CPU | "
              "step ms | baseline step ms | baseline/this step | newton/solve | "
              "baseline newton/solve | roofline | vertex ms | baseline vertex ms | "
              "baseline/this vertex |%s\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|%s\n",
              anyLines ? " lines/boat |" : "", anyLines ? "---|" : "");
  int rc = 0;
  for (int t : tris) {
    for (int nb : boats) {
      for (const std::string& be : backends) {
        for (const auto& kind : kinds) {
          std::vector<std::string> common = {
              "--meshes", meshes, "--boats", std::to_string(nb), "--tris", std::to_string(t),
              "--backend", be, "--sea", kind.sea, "--pressure", kind.pressure,
              "--steps", std::to_string(steps), "--reps", "1"};
          if (gthreads >= 0) {
            common.push_back("--threads");
            common.push_back(std::to_string(gthreads));
          }
          if (gradiation >= 0) {
            common.push_back("--radiation");
            common.push_back(num(gradiation, "%.17g"));
          }
          if (!gradmem.empty()) {
            common.push_back("--radiation-memory");
            common.push_back(gradmem);
          }
          if (gwarmmem) common.push_back("--warm-memory");
          if (!ginteg.empty()) {  // both builds in the same mode
            common.push_back("--integration");
            common.push_back(ginteg);
          }
          if (kind.lines > 0) {  // only then: a baseline without --lines runs the rest
            for (const std::string& a : {std::string("--lines"), std::to_string(kind.lines),
                                         std::string("--segments"), std::to_string(gsegments)}) {
              common.push_back(a);
            }
          }
          if (gradoff) common.push_back("--radiation-off");
          CmpCell c{be, kind.sea, kind.pressure, nb, t};
          c.lines = kind.lines;
          if (!compareCell(exe, base, common, dir, reps, &c)) {
            rc = 1;
            break;
          }
          out->push_back(c);
          std::printf("| %s | %s | %s | %d | %d | %.3f | %.3f | %.2f | %.3f | %.3f | %.2f | "
                      "%.3f | %.3f | %.2f | %s | %s | %.3f | %s | %s | %s |%s\n", be.c_str(), c.sea.c_str(),
                      c.pressure.c_str(), nb, t, c.hydro, c.bhydro, c.ratio, c.cpu, c.bcpu,
                      c.cratio, c.step, c.bstep, c.sratio,
                      num(c.newton, "%.3f").c_str(), num(c.bnewton, "%.3f").c_str(),
                      fraction(c.sea, c.ntri, c.cpu), num(c.vertex, "%.3f").c_str(),
                      num(c.bvertex, "%.3f").c_str(), num(c.vratio, "%.2f").c_str(),
                      anyLines ? (" " + std::to_string(c.lines) + " |").c_str() : "");
          std::fflush(stdout);
        }
        if (rc) break;
      }
      if (rc) break;
    }
    if (rc) break;
  }
  std::remove((std::string(dir) + "/cell.json").c_str());
  std::remove((std::string(dir) + "/stderr.txt").c_str());
  rmdir(dir);
  return rc;
}

// a JSON array of n rows to `json`, atomically (replaced only when complete):
// row(f, i) prints row i's object; 0, or 1 after printing why not
static int writeJsonArray(const std::string& json, size_t n,
                          const std::function<void(FILE*, size_t)>& row) {
  mjbtool::OutFile of;
  std::string e;
  if (!of.open(json, "--json", &e)) {
    std::fprintf(stderr, "mjbuoy-bench: %s\n", e.c_str());
    return 1;
  }
  FILE* f = of.file();
  std::fprintf(f, "[\n");
  for (size_t i = 0; i < n; i++) {
    std::fprintf(f, "  ");
    row(f, i);
    std::fprintf(f, "%s\n", i + 1 < n ? "," : "");
  }
  std::fprintf(f, "]\n");
  if (!of.commit(&e)) {
    std::fprintf(stderr, "mjbuoy-bench: %s\n", e.c_str());
    return 1;
  }
  return 0;
}

// --baseline's --json (if given), then stdout's state: the exit status
static int writeCompare(const std::string& json, const std::vector<CmpCell>& cc) {
  auto row = [&](FILE* f, size_t i) {
    const CmpCell& c = cc[i];
    std::fprintf(f, "{\"backend\": \"%s\", \"sea\": \"%s\", \"pressure\": \"%s\", "
                 "\"boats\": %d, \"tris\": %d, \"lines\": %d, \"hydro_ms\": %.6f, \"baseline_hydro_ms\": "
                 "%.6f, \"hydro_ratio\": %.6f, \"step_ms\": %.6f, \"baseline_step_ms\": %.6f, "
                 "\"step_ratio\": %.6f, \"hydro_cpu_ms\": %.6f, \"baseline_hydro_cpu_ms\": "
                 "%.6f, \"cpu_ratio\": %.6f}", c.backend.c_str(), c.sea.c_str(),
                 c.pressure.c_str(), c.boats, c.tris, c.lines, c.hydro, c.bhydro, c.ratio, c.step,
                 c.bstep, c.sratio, c.cpu, c.bcpu, c.cratio);
  };
  if (!json.empty() && writeJsonArray(json, cc.size(), row) != 0) return 1;
  if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
    std::fprintf(stderr, "mjbuoy-bench: cannot write the table to stdout\n");
    return 1;
  }
  return 0;
}

// the default --meshes: the installed models beside this executable
// (PREFIX/bin/../share/mjbuoy/models/meshes, found through /proc/self/exe so
// the installed bench works without the source tree), else the source
// tree's models/meshes of the build
static std::string defaultMeshes() {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    fs::path dir = exe.parent_path() / MJB_INSTALL_MODELS / "meshes";
    if (fs::is_directory(dir, ec)) return dir.lexically_normal().string();
  }
  return MJB_MODELS "/meshes";
}

int main(int argc, char** argv) {
  mjbtool::installMujocoHandlers("mjbuoy-bench");
  using mjbtool::Finite;
  CLI::App app{"Benchmark mjbuoy on the dissertation's grid of Wigley boats."};
  app.set_version_flag("--version", std::string("mjbuoy-bench ") + MJBUOY_VERSION_STRING);
  std::string grid = "small", json, meshes = defaultMeshes();
  std::vector<std::string> backends = {"cpu", "gl"};
  std::vector<int> boats, tris;
  int steps = 20, reps = 3;
  app.add_option("--grid", grid, "small (1, 50 boats x 64, 576 triangles) or full")
      ->check(CLI::IsMember({"small", "full"}));
  app.add_option("--backend", backends, "backends to measure")
      ->check(CLI::IsMember({"cpu", "gl"}));
  app.add_option("--boats", boats, "boat counts (overrides the grid)")->check(Finite(1, 100000));
  app.add_option("--tris", tris, "Wigley resolutions: 64 256 576 2800 7744 (overrides the grid)")
      ->check(CLI::IsMember({64, 256, 576, 2800, 7744}));
  app.add_option("--steps", steps, "steps per repetition")->check(Finite(1, 1e9));
  app.add_option("--reps", reps, "repetitions (the median is reported)")->check(Finite(1, 1e6));
  app.add_option("--threads", gthreads, "cpu threads (mjbuoy.threads; 0 = auto, the default)")
      ->check(Finite(0, 64));
  app.add_option("--json", json, "also write the results as JSON (replaced only when complete)");
  std::vector<std::string> seas = {"swell"}, pressures = {"linear"};
  app.add_option("--sea", seas, "seas, each measured in turn in every cell: flat, swell (one "
                 "Gerstner wave, the default), jonswap (64 components, short-crested) or "
                 "longcrested (the same spectrum, every component along 20 deg)")
      ->check(CLI::IsMember({"flat", "swell", "jonswap", "longcrested"}));
  app.add_option("--pressure", pressures, "pressure models (mjbuoy.sea.pressure), each "
                 "measured in turn: linear (the default) or kerner")
      ->check(CLI::IsMember({"linear", "kerner"}));
  app.add_option("--radiation", gradiation, "give every boat synthetic radiation coefficients "
                 "with this memory length [s] (0: added mass and its Kirchhoff terms only)")
      ->check(Finite(0, 60));
  app.add_option("--radiation-memory", gradmem, "with --radiation: the memory model "
                 "(mjbuoy.radiation.memorymodel): statespace (the default, a fitted "
                 "state-space model) or convolution")
      ->check(CLI::IsMember({"statespace", "convolution"}));
  app.add_flag("--radiation-off", gradoff, "mjbuoy.radiation off: no panel solve, added mass "
               "or memory (the boats are free, so it is on by default)");
  app.add_option("--seriestol", gseriestol, "mjbuoy.sea.seriestol: the cpu lanes' series "
                 "tolerance as a fraction of rho g V (0, the default: exact; not passed to "
                 "--baseline)")
      ->check(CLI::Range(0.0, 1e-4));
  app.add_option("--integration", ginteg, "mjbuoy.sea.integration: the cpu lanes' wave pressure, "
                 "exact (the default) or vertex (the components summed at the vertices); not "
                 "passed to --baseline")
      ->check(CLI::IsMember({"exact", "vertex"}));
  app.add_flag("--warm-memory", gwarmmem, "warm up until every boat's radiation memory "
               "history is full (its steady cost; about memory length / timestep steps, "
               "seconds to minutes for large cells) instead of 5 steps");
  std::vector<int> lines = {0};
  app.add_option("--lines", lines, "mooring lines per boat, each count measured in turn in "
                 "every cell (0, the default: unmoored), e.g. --lines 0 3 for moored against "
                 "unmoored: 20 m polyester ropes to anchors 15 m out on a bed 10 m down")
      ->check(Finite(0, 16));
  app.add_option("--segments", gsegments, "segments per mooring line (with --lines)")
      ->check(Finite(1, 1000));
  std::string baseline;
  app.add_option("--baseline", baseline, "another build's mjbuoy-bench binary: run every cell "
                 "with both, one repetition each in turn (A/B/A/B as child processes), and "
                 "print each cell's times and the ratio baseline/this");
  std::string sceneFile;
  app.add_option("--scene", sceneFile, "an MJCF scene timed as it is (its own hulls, sea, wind "
                 "and radiation) instead of the grid: hydro ms, full step ms and the real-time "
                 "factor (simulated s per wall s); --steps default 500 here, e.g. --scene "
                 "models/jonswap.xml")
      ->check(CLI::ExistingFile);
  app.add_option("--meshes", meshes, "directory of wigley_N.obj (default: the installed "
                 "share/mjbuoy/models/meshes beside this executable, else the source tree's)");
  {
    int rc = mjbtool::parseArgs(app, argc, argv, 1);  // docs: invalid input exits 1
    if (rc >= 0) return rc;
  }
  if (!sceneFile.empty()) {
    mjbtool::SceneArgs sa;
    sa.file = sceneFile;
    if (app.count("--backend")) sa.backend = backends.front();
    sa.steps = app.count("--steps") ? steps : 500;
    sa.reps = reps;
    sa.json = json;
    if (!json.empty()) {
      std::string e;
      if (!mjbtool::checkOutputs(sceneFile, {{json, "--json", true}}, &e)) {
        std::fprintf(stderr, "mjbuoy-bench: %s\n", e.c_str());
        return 1;
      }
    }
    if (baseline.empty()) return mjbtool::benchScene(sa);
    std::string e;
    if (!mjbtool::checkExecutable(baseline, "--baseline", &e)) {
      std::fprintf(stderr, "mjbuoy-bench: %s\n", e.c_str());
      return 1;
    }
    return mjbtool::compareScene(sa, baseline);
  }
  if (boats.empty()) boats = grid == "full" ? std::vector<int>{1, 50, 100, 200, 400, 800}
                                            : std::vector<int>{1, 50};
  if (tris.empty()) tris = grid == "full" ? std::vector<int>{64, 256, 576, 2800, 7744}
                                          : std::vector<int>{64, 576};
  if (!json.empty()) {
    std::vector<mjbtool::PathUse> uses;
    for (int t : tris) {
      uses.push_back({meshes + "/wigley_" + std::to_string(t) + ".obj", "mesh", false});
    }
    uses.push_back({json, "--json", true});
    std::string e;
    if (!mjbtool::checkWritable(json, "--json", &e) || !mjbtool::checkDistinct(uses, &e)) {
      std::fprintf(stderr, "mjbuoy-bench: %s\n", e.c_str());
      return 1;
    }
  }

  std::fprintf(stderr, "mjbuoy-bench: Wigley meshes from %s\n", meshes.c_str());
  // the seas and pressure models side by side in every cell, one after the other
  std::vector<Kind> kinds;
  for (const std::string& sea : seas) {
    for (const std::string& pm : pressures) {
      for (int nl : lines) kinds.push_back({sea, pm, nl});
    }
  }
  if (!baseline.empty()) {
    std::string e;
    if (!mjbtool::checkExecutable(baseline, "--baseline", &e)) {
      std::fprintf(stderr, "mjbuoy-bench: %s\n", e.c_str());
      return 1;
    }
    std::vector<CmpCell> cc;
    if (compareGrid(baseline, meshes, tris, boats, backends, kinds, steps, reps, &cc)) return 1;
    return writeCompare(json, cc);
  }
  std::vector<Cell> cells;
  int total = boats.size() * tris.size() * backends.size() * kinds.size();
  int done = 0;
  auto start = Clock::now();
  std::printf("| backend | sea | pressure | boats | tris/boat | triangles | hydro ms/step | step ms "
              "| bare step ms | step/bare | Mtri/s | paper GPU ms | hydro/paper | roofline "
              "| lines/boat |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (int t : tris) {
    for (int n : boats) {
      for (const std::string& be : backends) {
        for (const auto& kind : kinds) {
          gsea = kind.sea;
          gpress = kind.pressure;
          glines = kind.lines;
          Cell c;
          // fewer steps for huge cells so the grid finishes in minutes
          int st = std::max(2, std::min(steps, int(2e6 / double(n * t)) + 2));
          if (!run(meshes, n, t, be, st, reps, &c)) return 1;
          cells.push_back(c);
          double p = paper(n, t);
          std::printf("| %s | %s | %s | %d | %d | %d | %.3f | %.3f | %.3f | %.2f | %.1f | %s | %s "
                      "| %.3f | %d |\n", be.c_str(), gsea.c_str(), gpress.c_str(), n, t, c.ntri,
                      c.hydro, c.step, c.bare, c.step / c.bare, c.ntri / c.hydro / 1e3,
                      std::isnan(p) ? "" : std::to_string(p).c_str(),
                      std::isnan(p) ? "" : std::to_string(c.hydro / p).c_str(),
                      fraction(gsea, c.ntri, c.cpu), glines);
          std::fflush(stdout);
          double el = std::chrono::duration<double>(Clock::now() - start).count();
          done++;
          std::fprintf(stderr, "\rmjbuoy-bench: %d/%d cells, %.0f s elapsed, ~%.0f s left   ",
                       done, total, el, el / done * (total - done));
        }
      }
    }
  }
  std::fprintf(stderr, "\n");
  auto row = [&](FILE* f, size_t i) {
    const Cell& c = cells[i];
    std::fprintf(f, "{\"backend\": \"%s\", \"sea\": \"%s\", \"pressure\": \"%s\", "
                 "\"boats\": %d, \"tris\": %d, \"triangles\": %d, \"lines\": %d, "
                 "\"hydro_ms\": %.6f, \"hydro_cpu_ms\": %.6f, \"step_ms\": %.6f, \"bare_ms\": %.6f, ",
                 c.backend.c_str(), c.sea.c_str(), c.pressure.c_str(), c.boats, c.tris, c.ntri, c.lines,
                 c.hydro, c.cpu, c.step, c.bare);
    if (std::isfinite(c.newton)) std::fprintf(f, "\"newton_per_solve\": %.6f, ", c.newton);
    if (std::isfinite(c.vertex)) std::fprintf(f, "\"vertex_ms\": %.6f, ", c.vertex);
    std::fprintf(f, "\"roofline_ns\": %.6f, \"roofline_fraction\": %.6f, ", roofline(c.sea),
                 fraction(c.sea, c.ntri, c.cpu));
    std::fprintf(f, "\"stages\": {");
    for (size_t j = 0; j < c.stages.size(); j++) {
      std::fprintf(f, "%s\"%s\": %.6f", j ? ", " : "", c.stages[j].first.c_str(),
                   c.stages[j].second);
    }
    std::fprintf(f, "}}");
  };
  if (!json.empty() && writeJsonArray(json, cells.size(), row) != 0) return 1;
  if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
    std::fprintf(stderr, "mjbuoy-bench: cannot write the table to stdout\n");
    return 1;
  }
  return 0;
}
