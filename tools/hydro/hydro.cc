// mjbuoy-hydro: print the radiation coefficients mjbuoy computes at attach
// for each hull body with radiation on (docs/mjcf.md section 11):
// A_inf, A(omega), B(omega), the retardation function K(t) and the
// exciting force X(omega, heading) with its Froude-Krylov part, and the
// roll stiffness and viscous roll damping it applies; --write and --convert:
// coefficient files of WAMIT, Capytaine and BEMIO (docs/interchange.md)
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <mujoco/mujoco.h>

#include "api/buoy.h"
#include "api/coefexport.h"
#include "cliopt.h"
#include "guard.h"
#include "hydroio.h"
#include "hydroplot.h"
#include "mjbuoy.h"
#include "modelload.h"
#include "outfile.h"
#include "radiation/coefxform.h"
#include "radnotice.h"
#include "radiation/radiation.h"
#include "radiation/radtail.h"

static const char* kDof[6] = {"surge", "sway", "heave", "roll", "pitch", "yaw"};

// one body's tables; false on a write error
static bool printBody(FILE* o, const mjModel* m, int body, const mjb::HydroCoef& c,
                      const mjb::Radiation& r, double dt, double tk) {
  std::fprintf(o, "# body \"%s\": reference point (its COM) %.6g %.6g %.6g m in body axes, "
               "rho %g kg/m^3, g %g m/s^2, deep water\n", m->names + m->name_bodyadr[body],
               c.ref[0], c.ref[1], c.ref[2], c.rho, c.g);
  // the viscous roll damping the step applies (docs/physics.md section 14,
  // "Viscous roll damping")
  for (const mjb::RadBody& x : r.rb)
    if (x.body == body)
      std::fprintf(o, "# roll about the body x axis: hydrostatic C44 %.6g N m/rad (about the "
                   "COM), viscous damping B_1 %.6g N m s/rad, B_2 %.6g N m s^2/rad^2 "
                   "(rolldamping plus rollzeta of critical)\n", x.c44, x.roll[0], x.roll[1]);
  std::fprintf(o, "# A_inf (6x6, rows force/moment, columns surge..yaw) [kg, kg m, kg m^2]\n");
  for (int i = 0; i < 6; i++) {
    for (int j = 0; j < 6; j++) std::fprintf(o, "%s%.6g", j ? " " : "", c.Ainf[6 * i + j]);
    std::fprintf(o, "\n");
  }
  std::fprintf(o, "\n# omega[rad/s]");
  for (int i = 0; i < 6; i++) std::fprintf(o, " A_%s", kDof[i]);
  for (int i = 0; i < 6; i++) std::fprintf(o, " B_%s", kDof[i]);
  std::fprintf(o, "   (diagonal; A [kg, kg m^2], B [kg/s, kg m^2/s])\n");
  for (int w = 0; w < c.nw(); w++) {
    std::fprintf(o, "%.6g", c.omega[w]);
    for (int i = 0; i < 6; i++) std::fprintf(o, " %.6g", c.A[36 * w + 7 * i]);
    for (int i = 0; i < 6; i++) std::fprintf(o, " %.6g", c.B[36 * w + 7 * i]);
    std::fprintf(o, "\n");
  }
  int n = (int)std::floor(tk / dt) + 1;
  std::vector<std::vector<double>> K(6, std::vector<double>(n));
  double pt[6];
  mjb::tailExponents(c, pt);
  for (int i = 0; i < 6; i++) mjb::retardationP(c, pt, i, i, dt, n, K[i].data());
  std::fprintf(o, "\n# tail beyond the last frequency, B_ii(w) = B_ii(w_N) (w_N / w)^p_i, p (0: none):");
  for (int i = 0; i < 6; i++) std::fprintf(o, " %.6g", pt[i]);
  std::fprintf(o, "\n# t[s]");
  for (int i = 0; i < 6; i++) std::fprintf(o, " K_%s", kDof[i]);
  std::fprintf(o, "   (retardation function, diagonal [N/m, N m/rad] per s)\n");
  for (int k = 0; k < n; k++) {
    std::fprintf(o, "%.6g", k * dt);
    for (int i = 0; i < 6; i++) std::fprintf(o, " %.6g", K[i][k]);
    std::fprintf(o, "\n");
  }
  std::fprintf(o, "\n");
  return !std::ferror(o);
}

// the exciting force table of the body's diffraction (when on); false on a
// write error
static bool printX(FILE* o, const mjb::DiffBody& b) {
  // the table's axes (the body's heading at qpos0) to the world's: the
  // headings turn by yaw0 (coefxform.h)
  mjb::HydroCoef c = b.c;
  const double cy = std::cos(b.yaw0), sy = std::sin(b.yaw0);
  const double Rw[9] = {cy, sy, 0, -sy, cy, 0, 0, 0, 1};
  c.A.assign(36 * c.omega.size(), 0);
  c.B = c.A;
  if (b.yaw0 != 0 && !mjb::coefTransform(&c, c.ref, Rw, c.ref).empty()) return false;
  std::fprintf(o, "# exciting force X per unit wave amplitude and its Froude-Krylov part FK, "
               "about the COM, in the world axes of the initial pose (qpos0); heading: "
               "direction of travel from +x [deg]; phase [deg]: the force is Re(a X "
               "e^{-i omega t}) for a wave of complex amplitude a at the COM\n# omega[rad/s] "
               "heading[deg]");
  for (const char* w : {"X", "FK"}) {
    for (int i = 0; i < 6; i++) std::fprintf(o, " |%s_%s|", w, kDof[i]);
    for (int i = 0; i < 6; i++) std::fprintf(o, " arg%s_%s", w, kDof[i]);
  }
  std::fprintf(o, "   ([N/m, N m/m], deg)\n");
  for (int w = 0; w < c.nw(); w++)
    for (int h = 0; h < c.nh(); h++) {
      std::fprintf(o, "%.6g %.6g", c.omega[w], c.heading[h] * 180 / M_PI);
      size_t k = 6 * ((size_t)w * c.nh() + h);
      for (const auto* p : {&c.Xre, &c.FKre}) {
        const double* re = p->data() + k;
        const double* im = (p == &c.Xre ? c.Xim : c.FKim).data() + k;
        for (int i = 0; i < 6; i++) std::fprintf(o, " %.6g", std::hypot(re[i], im[i]));
        for (int i = 0; i < 6; i++) std::fprintf(o, " %.6g", std::atan2(im[i], re[i]) * 180 / M_PI);
      }
      std::fprintf(o, "\n");
    }
  std::fprintf(o, "\n");
  return !std::ferror(o);
}

// --write: the coefficients of body wbody (or the first) to files; 0 or 1
static int writeBody(const mjb::Buoy& B, const mjModel* m, const std::string& wbody,
                     const std::vector<std::string>& writes, const mjb::CoefOpt& o,
                     std::string* e) {
  size_t i = 0;
  while (!wbody.empty() && i < B.coef.size() && wbody != m->names + m->name_bodyadr[B.coef[i].first])
    i++;
  if (i == B.coef.size()) {
    *e = "--write-body " + wbody + ": no body of that name has radiation";
    return 1;
  }
  int body = B.coef[i].first;
  mjb::CoefFile f;
  *e = mjb::exportCoef(B, body, &f);
  if (!e->empty()) {
    *e = "--write-body " + std::string(m->names + m->name_bodyadr[body]) + ": " + *e;
    return 1;
  }
  if (!mjbhydro::writeAll(writes, o, f, e)) return 1;
  const double* c = B.coef[i].second.ref;
  std::fprintf(stderr, "mjbuoy-hydro: wrote body \"%s\" about its COM, in its axes: read it back "
               "with <numeric name=\"mjbuoy.radiation.fileorigin.%s\" data=\"%.17g %.17g "
               "%.17g\"/>\n", m->names + m->name_bodyadr[body], m->names + m->name_bodyadr[body],
               c[0], c[1], c[2]);
  return 0;
}

// --convert: one coefficient file into the --write files; 0 or 1
static int convertFile(const std::string& in, const std::string& model,
                       const std::vector<std::string>& writes, const mjb::CoefOpt& o) {
  std::string e;
  std::vector<mjbtool::PathUse> uses = {{in, "--convert", false}};
  for (const std::string& w : writes)
    for (const std::string& p : mjbhydro::outputsOf(w)) uses.push_back({p, "--write", true});
  if (!model.empty()) {
    e = "--convert reads no model (" + model + ")";
  } else if (writes.empty()) {
    e = "--convert needs --write FILE";
  } else if (mjbtool::checkDistinct(uses, &e)) {
    mjb::CoefFile f;
    e = mjb::readCoefFile(in, o, &f);
    if (e.empty()) mjbhydro::writeAll(writes, o, f, &e);
    if (e.empty())
      std::fprintf(stderr, "mjbuoy-hydro: %s: %d frequencies, %d headings%s%s%s\n", in.c_str(),
                   f.c.nw(), f.c.nh(), f.hasAinf ? ", A_inf" : "", f.hasFK ? ", Froude-Krylov" : "",
                   f.hasC ? ", hydrostatics" : "");
  }
  if (e.empty()) return 0;
  std::fprintf(stderr, "mjbuoy-hydro: %s\n", e.c_str());
  return 1;
}

int main(int argc, char** argv) {
  CLI::App app{"Compute and print the radiation coefficients of each hull body with "
               "radiation on (mjbuoy.radiation, docs/mjcf.md section 11): A_inf, A(omega), "
               "B(omega) about the body COM in body axes, K(t), and the exciting force X(omega, heading) "
               "with its Froude-Krylov part (with mjbuoy.radiation.diffraction on). The panel "
               "solutions go into the radiation cache (mjbuoy.radiation.cache, else "
               "$MJBUOY_RADIATION_CACHE, else $XDG_CACHE_HOME/mjbuoy or ~/.cache/mjbuoy), so running "
               "it once precomputes them for every later attach of the model."};
  app.set_version_flag("--version", std::string("mjbuoy-hydro ") + MJBUOY_VERSION_STRING);
  mjbtool::installProgress("mjbuoy-hydro");
  std::string model, file;
  double dt = 0.05, tk = 0;
  using mjbtool::Finite;
  app.add_option("model", model, "MJCF model with mjbuoy.radiation on (not with --convert)");
  std::vector<std::string> writes;
  std::string wbody, convert;
  mjb::CoefOpt copt;
  app.add_option("--write", writes, "also write the coefficients of one body to this file, "
                 "its format by its name: WAMIT stem.1 (writes stem.1, stem.3, stem.3fk), "
                 "Capytaine NetCDF .nc, BEMIO HDF5 .h5 (docs/interchange.md); repeatable");
  app.add_option("--write-body", wbody, "the body --write writes (default: the first with "
                 "radiation)");
  app.add_option("--convert", convert, "read this coefficient file (WAMIT .1, Capytaine .nc, "
                 "BEMIO .h5) instead of a model and write it with --write");
  app.add_option("--ulen", copt.ulen, "WAMIT's length scale ULEN [m] of files read and "
                 "written")->check(Finite(1e-6, 1e6));
  app.add_option("--rho", copt.rho, "water density [kg/m^3] of WAMIT files read by --convert "
                 "(WAMIT's numbers are per rho)")->check(Finite(1, 1e5));
  app.add_option("--g", copt.g, "gravity [m/s^2] of WAMIT files read by --convert")
      ->check(Finite(0.1, 100));
  app.add_option("--kt-step", dt, "time step of the K(t) table [s]")->check(Finite(1e-4, 10));
  app.add_option("--kt-length", tk, "length of the K(t) table [s]; 0: the automatic memory "
                 "length")->check(Finite(0, mjb::kMaxMemory));
  app.add_option("-o,--output", file, "file to write, replaced only when complete "
                 "(default: stdout)");
  std::string png, pbody;
  app.add_option("--plot", png, "also draw A_ii(omega), B_ii(omega) and K_ii(t) of one body "
                 "into this PNG with gnuplot (package gnuplot-nox)");
  app.add_option("--plot-body", pbody, "the body --plot draws (default: the first with "
                 "radiation)");
  {
    int rc = mjbtool::parseArgs(app, argc, argv, 1);  // docs: invalid input exits 1
    if (rc >= 0) return rc;
  }
  if (!convert.empty()) return convertFile(convert, model, writes, copt);
  if (model.empty()) {
    std::fprintf(stderr, "mjbuoy-hydro: give a model (or --convert FILE)\n");
    return 1;
  }

  std::string e;
  {
    // outputs never replace the model, its files or each other (before anything is computed)
    std::vector<mjbtool::PathUse> uses;
    if (!file.empty()) uses.push_back({file, "-o", true});
    if (!png.empty()) uses.push_back({png, "--plot", true});
    for (const std::string& w : writes)
      for (const std::string& o : mjbhydro::outputsOf(w)) uses.push_back({o, "--write", true});
    if (!mjbtool::checkOutputs(model, uses, &e)) {
      std::fprintf(stderr, "mjbuoy-hydro: %s\n", e.c_str());
      return 1;
    }
  }
  char err[1024] = "";
  std::string lerr;
  mjModel* m = mjbtool::loadModel(model, nullptr, "", &lerr);
  if (!m) {
    std::fprintf(stderr, "mjbuoy-hydro: %s\n", lerr.c_str());
    return 1;
  }
  std::string plan = mjbtool::radiationPlan(m);  // the panel solve is no silent wait
  if (!plan.empty()) std::fprintf(stderr, "mjbuoy-hydro: %s\n", plan.c_str());
  mjbBuoy* b = mjb_attach(m, "cpu", err, sizeof err);
  if (!b) {
    std::fprintf(stderr, "mjbuoy-hydro: %s\n", err);
    mj_deleteModel(m);
    return 1;
  }
  if (mjb_warnings(b)[0]) std::fprintf(stderr, "%s", mjb_warnings(b));
  const mjb::Buoy* B = mjb::buoyOf(b);
  std::string dir = mjb::radCacheDir(B->cfg.rad.cache);
  std::fprintf(stderr, "mjbuoy-hydro: radiation cache %s: %d body(ies) read, %d computed, %d "
               "written, %d the same as an identical hull's\n", dir.empty() ? "off" : dir.c_str(),
               B->radcache.hit, B->radcache.miss, B->radcache.write, B->radcache.same);
  int rc = 0;
  if (B->coef.empty()) {
    std::fprintf(stderr, "mjbuoy-hydro: %s has no hull body with radiation on; add <text "
                 "name=\"mjbuoy.radiation\" data=\"on\"/> to its <custom> section\n",
                 model.c_str());
    rc = 1;
  }
  mjbtool::OutFile of;
  if (!rc && !file.empty() && !of.open(file, "-o", &e)) {
    std::fprintf(stderr, "mjbuoy-hydro: %s\n", e.c_str());
    rc = 1;
  }
  FILE* o = file.empty() ? stdout : of.file();
  for (size_t i = 0; !rc && i < B->coef.size(); i++) {
    const mjb::HydroCoef& c = B->coef[i].second;
    double len = tk > 0 ? tk : mjb::memoryLength(c);
    if (!printBody(o, m, B->coef[i].first, c, B->rad, dt, len)) rc = 1;
    for (const mjb::DiffBody& db : B->diff.db)
      if (!rc && db.body == B->coef[i].first && !printX(o, db)) rc = 1;
  }
  if (!rc && (std::fflush(o) != 0 || std::ferror(o))) rc = 1;
  if (!rc && !png.empty()) {
    size_t i = 0;
    while (!pbody.empty() && i < B->coef.size() &&
           pbody != m->names + m->name_bodyadr[B->coef[i].first])
      i++;
    if (i == B->coef.size()) {
      e = "--plot-body " + pbody + ": no body of that name has radiation";
      rc = 1;
    } else {
      const mjb::HydroCoef& c = B->coef[i].second;
      double len = tk > 0 ? tk : mjb::memoryLength(c);
      int n = (int)std::floor(len / dt) + 1;
      std::vector<std::vector<double>> K(6, std::vector<double>(n));
      double pt[6];
      mjb::tailExponents(c, pt);
      for (int k = 0; k < 6; k++) mjb::retardationP(c, pt, k, k, dt, n, K[k].data());
      std::string name = m->names + m->name_bodyadr[B->coef[i].first];
      if (!mjbhydro::plotCoef(png, "radiation of body " + name + " (" + model + ")", c, K, dt,
                              &e))
        rc = 1;
    }
  }
  if (!rc && !writes.empty()) rc = writeBody(*B, m, wbody, writes, copt, &e);
  if (!rc && !file.empty() && !of.commit(&e)) rc = 1;
  if (rc && B && !B->coef.empty()) {
    if (e.empty()) e = std::string("write failed on ") + (file.empty() ? "stdout" : file.c_str());
    std::fprintf(stderr, "mjbuoy-hydro: %s\n", e.c_str());
  }
  mjb_detach(b);
  mj_deleteModel(m);
  return rc;
}
