// set_sea and radiation of mjbuoy.Sim: Python values to mjb_setSea's
// mjbSea, the panel solver's HydroCoef to numpy
#include <cmath>
#include <complex>
#include <cstring>
#include <string>

#include "api/buoy.h"
#include "bind.h"
#include <pybind11/complex.h>

namespace mjbpy {

// a float field of a dict, checked finite
static double number(py::handle v, const std::string& what) {
  if (v.is_none() || !(py::isinstance<py::int_>(v) || py::isinstance<py::float_>(v))) {
    throw py::type_error(what + ": expected a number, got " +
                         py::str(py::type::of(v)).cast<std::string>());
  }
  double x = v.cast<double>();
  if (!std::isfinite(x)) throw py::value_error(what + " is not finite");
  return x;
}

static long long whole(py::handle v, const std::string& what) {
  if (!py::isinstance<py::int_>(v)) throw py::type_error(what + ": expected a whole number");
  return v.cast<long long>();
}

static std::string word(py::handle v, const std::string& what) {
  if (!py::isinstance<py::str>(v)) throw py::type_error(what + ": expected a string");
  return v.cast<std::string>();
}

static void spectrumOf(py::handle obj, int i, mjbSpectrum* s, std::vector<double>* table) {
  std::string at = "spectra[" + std::to_string(i) + "]";
  if (!py::isinstance<py::dict>(obj)) throw py::type_error(at + ": expected a dict");
  mjb_defaultSpectrum(s);
  for (auto kv : obj.cast<py::dict>()) {
    std::string k = py::str(kv.first).cast<std::string>(), what = at + "[\"" + k + "\"]";
    py::handle v = kv.second;
    if (k == "type") {
      std::string t = word(v, what);
      if (t == "pm") s->type = mjbSPEC_PM;
      else if (t == "jonswap") s->type = mjbSPEC_JONSWAP;
      else if (t == "table") s->type = mjbSPEC_TABLE;
      else throw py::value_error(what + " = \"" + t + "\"; accepted: pm, jonswap, table");
    } else if (k == "hs") s->hs = number(v, what);
    else if (k == "tp") s->tp = number(v, what);
    else if (k == "wind") s->wind = number(v, what);
    else if (k == "gamma") s->gamma = number(v, what);
    else if (k == "dir") s->dir = number(v, what);
    else if (k == "spread") s->spread = number(v, what);
    else if (k == "wmin") s->wmin = number(v, what);
    else if (k == "wmax") s->wmax = number(v, what);
    else if (k == "n") s->n = (int)whole(v, what);
    else if (k == "seed") {
      long long x = whole(v, what);
      if (x < 0) throw py::value_error(what + " is negative");
      s->seed = (unsigned long long)x;
    } else if (k == "table") {
      py::array_t<double> a = doubles(v, what.c_str(), {-1, 2});
      table->assign(a.data(), a.data() + a.size());
      s->ntable = (int)a.shape(0);
    } else {
      throw py::value_error(what + ": unknown key; accepted: type, hs, tp, wind, gamma, table, "
                            "dir, spread, n, wmin, wmax, seed");
    }
  }
}

static void windOf(py::handle obj, mjbWind* w) {
  if (!py::isinstance<py::dict>(obj)) throw py::type_error("wind: expected a dict");
  w->ngust = 64;
  w->seed = 1;
  for (auto kv : obj.cast<py::dict>()) {
    std::string k = py::str(kv.first).cast<std::string>(), what = "wind[\"" + k + "\"]";
    py::handle v = kv.second;
    if (k == "speed") w->speed = number(v, what);
    else if (k == "dir") w->dir = number(v, what);
    else if (k == "ngust") w->ngust = (int)whole(v, what);
    else if (k == "seed") {
      long long x = whole(v, what);
      if (x < 0) throw py::value_error(what + " is negative");
      w->seed = (unsigned long long)x;
    } else if (k == "gust") {
      std::string g = word(v, what);
      if (g == "none") w->gust = mjbGUST_NONE;
      else if (g == "froya") w->gust = mjbGUST_FROYA;
      else throw py::value_error(what + " = \"" + g + "\"; accepted: none, froya");
    } else {
      throw py::value_error(what + ": unknown key; accepted: speed, dir, gust, ngust, seed");
    }
  }
}

void setSea(mjbBuoy* b, py::object waves, py::object spectra, py::object current,
            py::object wind, py::object ramp) {
  mjbSea sea;
  std::memset(&sea, 0, sizeof(sea));
  // no ramp given: the model's (mjb_setSea's negative)
  sea.ramp = ramp.is_none() ? -1.0 : ramp.cast<double>();
  py::array_t<double> wv;
  if (!waves.is_none()) {
    wv = doubles(waves, "waves", {-1, 5});
    sea.wave = wv.data();
    sea.nwave = (int)wv.shape(0);
  }
  std::vector<mjbSpectrum> spec;
  std::vector<std::vector<double>> tables;
  if (!spectra.is_none()) {
    if (py::isinstance<py::dict>(spectra)) throw py::type_error("spectra: give a list of dicts");
    py::list l = py::list(spectra);
    spec.resize(l.size());
    tables.resize(l.size());
    for (size_t i = 0; i < l.size(); i++) {
      spectrumOf(l[i], (int)i, &spec[i], &tables[i]);
      if (!tables[i].empty()) spec[i].table = tables[i].data();
    }
    sea.spectrum = spec.data();
    sea.nspectrum = (int)spec.size();
  }
  if (!current.is_none()) {
    py::array_t<double> c = doubles(current, "current", {2});
    sea.current[0] = c.at(0);
    sea.current[1] = c.at(1);
  }
  if (!wind.is_none()) windOf(wind, &sea.wind);
  char e[1024] = "";
  if (!mjb_setSea(b, &sea, e, sizeof(e))) throw Error(e);
}

// n x 36 (row-major 6 x 6 blocks) as (n, 6, 6)
static py::array blocks(const double* p, int n) {
  py::array_t<double> a({n, 6, 6});
  if (n) std::memcpy(a.mutable_data(), p, sizeof(double) * 36 * n);
  return a;
}

static py::array complexOf(const std::vector<double>& re, const std::vector<double>& im, int nw,
                           int nh) {
  py::array_t<std::complex<double>> a({nw, nh, 6});
  std::complex<double>* o = a.mutable_data();
  for (size_t i = 0; i < re.size() && i < (size_t)a.size(); i++) o[i] = {re[i], im[i]};
  return a;
}

py::dict radiationOf(const World& w, int body) {
  const mjb::Buoy* B = mjb::buoyOf(w.b);
  std::string have;
  for (const auto& bc : B->coef) {
    if (bc.first == body) {
      const mjb::HydroCoef& c = bc.second;
      py::dict d;
      int nw = c.nw();
      d["omega"] = py::array_t<double>(nw, c.omega.data());
      d["A"] = blocks(c.A.data(), nw);
      d["B"] = blocks(c.B.data(), nw);
      py::array a = blocks(c.Ainf, 1);
      d["Ainf"] = a.attr("reshape")(6, 6);
      // the exciting force of the diffraction solution (mjbuoy.radiation.diffraction,
      // on by default), as mjbuoy-hydro prints it: about the COM, world axes at qpos0
      const mjb::HydroCoef* x = &c;
      for (const mjb::DiffBody& db : B->diff.db) {
        if (db.body == body) x = &db.c;
      }
      int nhx = x->nh(), nwx = x->nw();
      d["heading"] = py::array_t<double>(nhx, x->heading.data());
      d["X"] = complexOf(x->Xre, x->Xim, nwx, nhx);
      d["FK"] = complexOf(x->FKre, x->FKim, nwx, nhx);
      d["ref"] = py::array_t<double>(3, c.ref);
      d["rho"] = c.rho;
      d["g"] = c.g;
      d["depth"] = c.depth;
      return d;
    }
    const char* n = mj_id2name(w.m, mjOBJ_BODY, bc.first);
    have += std::string(have.empty() ? "" : ", ") + (n ? n : std::to_string(bc.first));
  }
  const char* n = mj_id2name(w.m, mjOBJ_BODY, body);
  throw Error("body " + std::string(n ? n : std::to_string(body)) +
              " has no radiation coefficients; " +
              (have.empty() ? "the scene has radiation off: set mjbuoy.radiation=\"on\" "
                              "(docs/mjcf.md section 11)"
                            : "bodies with them: " + have));
}

}  // namespace mjbpy
