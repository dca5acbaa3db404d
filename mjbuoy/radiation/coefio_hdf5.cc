// coefio_hdf5: WEC-Sim's BEMIO HDF5 file (coefio.h; docs/interchange.md).
// BEMIO (WEC-Sim, source/functions/BEMIO/writeBEMIOH5.m) stores, per body n
// (group body<n>), in C order (MATLAB's arrays with their axes reversed):
//   hydro_coeffs/added_mass/all          [6][6 N][nw]  A / rho
//   hydro_coeffs/added_mass/inf_freq     [6][6 N]      A_inf / rho
//   hydro_coeffs/radiation_damping/all   [6][6 N][nw]  B / (rho omega)
//   hydro_coeffs/excitation/{re,im,mag,phase}                 [6][nh][nw]  X / (rho g)
//   hydro_coeffs/excitation/{froude-krylov,scattering}/{...}  the same for its parts
//   hydro_coeffs/linear_restoring_stiffness                   [6][6]  C / (rho g)
// and simulation_parameters/{rho, g, w [rad/s], T, wave_dir [deg], water_depth};
// rows are the force, columns the motion; the exciting force follows WAMIT's
// e^{+i omega t} (BEMIO conjugates Capytaine's), so mjbuoy's X is its conjugate
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "radiation/coefio.h"
#include "util/fmt.h"

namespace mjb {

// a dataset as doubles with its dims; false if absent or unreadable
static bool h5Get(hid_t f, const std::string& name, std::vector<double>* v,
                  std::vector<hsize_t>* dims) {
  if (H5Lexists(f, name.c_str(), H5P_DEFAULT) <= 0) return false;
  hid_t d = H5Dopen2(f, name.c_str(), H5P_DEFAULT);
  if (d < 0) return false;
  hid_t s = H5Dget_space(d);
  int nd = s < 0 ? -1 : H5Sget_simple_extent_ndims(s);
  bool ok = nd >= 0 && nd <= 4;
  if (ok) {
    dims->assign(nd, 0);
    H5Sget_simple_extent_dims(s, dims->data(), nullptr);
    hsize_t n = 1;
    for (hsize_t x : *dims) n *= x;
    ok = n < (hsize_t(1) << 28);
    if (ok) v->resize(n);
    ok = ok && (!n || H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v->data()) >= 0);
  }
  if (s >= 0) H5Sclose(s);
  H5Dclose(d);
  return ok;
}

// whether each group on the way to name exists (H5Lexists needs them)
static bool h5Has(hid_t f, const std::string& name) {
  for (size_t p = name.find('/', 1); ; p = name.find('/', p + 1)) {
    std::string s = p == std::string::npos ? name : name.substr(0, p);
    if (H5Lexists(f, s.c_str(), H5P_DEFAULT) <= 0) return false;
    if (p == std::string::npos) return true;
  }
}

static bool get(hid_t f, const std::string& name, std::vector<double>* v,
                std::vector<hsize_t>* dims) {
  return h5Has(f, name) && h5Get(f, name, v, dims);
}

static std::string readAll(hid_t f, const std::string& path, const CoefOpt& o, CoefFile* cf) {
  HydroCoef& c = cf->c;
  std::vector<double> v;
  std::vector<hsize_t> d;
  const std::string bad = "BEMIO file " + path + ": ";
  if (get(f, "/simulation_parameters/rho", &v, &d) && v.size() == 1) c.rho = v[0];
  if (get(f, "/simulation_parameters/g", &v, &d) && v.size() == 1) c.g = v[0];
  if (get(f, "/simulation_parameters/water_depth", &v, &d) && v.size() == 1 && std::isfinite(v[0]))
    c.depth = v[0];
  std::vector<double> w, head;
  if (!get(f, "/simulation_parameters/w", &w, &d))
    return bad + "no /simulation_parameters/w (the frequencies); is it a BEMIO file?";
  get(f, "/simulation_parameters/wave_dir", &head, &d);
  std::string b = "/body" + std::to_string(o.body);
  if (!h5Has(f, b)) return bad + "has no group " + b + "; give the body's number (1-based)";
  int col = 6 * (o.body - 1);
  if (get(f, b + "/properties/dof_start", &v, &d) && v.size() == 1) col = (int)v[0] - 1;
  size_t nw = w.size();
  std::vector<double> A, B;
  std::vector<hsize_t> da, db;
  if (!get(f, b + "/hydro_coeffs/added_mass/all", &A, &da) ||
      !get(f, b + "/hydro_coeffs/radiation_damping/all", &B, &db))
    return bad + b + "/hydro_coeffs has no added_mass/all or radiation_damping/all";
  if (da.size() != 3 || da[0] != 6 || da[2] != nw || da[1] < (hsize_t)col + 6 || db != da)
    return bad + b + "/hydro_coeffs/added_mass/all must be [6][6 N][nw] with nw = " +
           std::to_string(nw) + " frequencies";
  size_t m = da[1];
  // frequencies in increasing order; 0 and infinity left out
  std::vector<size_t> rows;
  for (size_t k = 0; k < nw; k++)
    if (w[k] > 0 && std::isfinite(w[k])) rows.push_back(k);
  std::sort(rows.begin(), rows.end(), [&](size_t a, size_t e) { return w[a] < w[e]; });
  for (size_t r : rows) c.omega.push_back(w[r]);
  for (size_t q = 0; q < rows.size(); q++)
    for (int i = 0; i < 6; i++)
      for (int j = 0; j < 6; j++) {
        size_t s = (i * m + col + j) * nw + rows[q];
        c.A.push_back(A[s] * c.rho);
        c.B.push_back(B[s] * c.rho * w[rows[q]]);
      }
  if (get(f, b + "/hydro_coeffs/added_mass/inf_freq", &v, &d) && d.size() == 2 && d[0] == 6 &&
      d[1] == m) {
    for (int i = 0; i < 6; i++)
      for (int j = 0; j < 6; j++) c.Ainf[6 * i + j] = v[i * m + col + j] * c.rho;
    cf->hasAinf = true;
  }
  if (get(f, b + "/hydro_coeffs/linear_restoring_stiffness", &v, &d) && v.size() == 36) {
    for (int k = 0; k < 36; k++) cf->C[k] = v[k] * c.rho * c.g;
    cf->hasC = true;
  }
  if (get(f, b + "/properties/disp_vol", &v, &d) && v.size() == 1) cf->vol = v[0];
  if (get(f, b + "/properties/cg", &v, &d) && v.size() == 3)
    for (int k = 0; k < 3; k++) cf->cg[k] = v[k];
  std::vector<double> xr, xi, fr, fi;
  std::vector<hsize_t> dx, d2, d3, d4;
  const std::string ex = b + "/hydro_coeffs/excitation/";
  if (!get(f, ex + "re", &xr, &dx) || !get(f, ex + "im", &xi, &d2)) return "";
  size_t nh = head.size();
  if (dx.size() != 3 || dx[0] != 6 || dx[1] != nh || dx[2] != nw || d2 != dx)
    return bad + ex + "re and im must be [6][nh][nw] with nh = " + std::to_string(nh) +
           " headings (simulation_parameters/wave_dir) and nw = " + std::to_string(nw);
  bool fk = get(f, ex + "froude-krylov/re", &fr, &d3) && get(f, ex + "froude-krylov/im", &fi, &d4) &&
            d3 == dx && d4 == dx;
  for (double h : head) c.heading.push_back(h * M_PI / 180);
  for (size_t q = 0; q < rows.size(); q++)
    for (size_t h = 0; h < nh; h++)
      for (int i = 0; i < 6; i++) {
        size_t s = (i * nh + h) * nw + rows[q];
        double sc = c.rho * c.g;
        c.Xre.push_back(xr[s] * sc);
        c.Xim.push_back(-xi[s] * sc);  // e^{+i omega t} to e^{-i omega t}
        c.FKre.push_back(fk ? fr[s] * sc : 0);
        c.FKim.push_back(fk ? -fi[s] * sc : 0);
      }
  cf->hasX = true;
  cf->hasFK = fk;
  return "";
}

std::string readBemio(const std::string& path, const CoefOpt& o, CoefFile* f) {
  H5E_auto2_t fn;
  void* data;
  H5Eget_auto2(H5E_DEFAULT, &fn, &data);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors come back as messages, not prints
  hid_t h = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  std::string e;
  if (h < 0) {
    e = "BEMIO file " + path + " cannot be opened as HDF5 (missing, unreadable or not HDF5)";
  } else {
    e = readAll(h, path, o, f);
    H5Fclose(h);
  }
  H5Eset_auto2(H5E_DEFAULT, fn, data);
  return e;
}

// writer: datasets by path, intermediate groups made on the way
struct H5W {
  hid_t f;
  hid_t lcpl;
  bool ok = true;
  void put(const std::string& name, const std::vector<hsize_t>& dims, const double* v,
           const char* desc, const char* unit) {
    if (!ok) return;
    hid_t s = H5Screate_simple((int)dims.size(), dims.data(), nullptr);
    hid_t d = H5Dcreate2(f, name.c_str(), H5T_IEEE_F64LE, s, lcpl, H5P_DEFAULT, H5P_DEFAULT);
    ok = s >= 0 && d >= 0 && H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v) >= 0;
    ok = ok && attr(d, "description", desc) && attr(d, "units", unit);
    if (d >= 0) H5Dclose(d);
    if (s >= 0) H5Sclose(s);
  }
  void put1(const std::string& name, double v, const char* desc, const char* unit) {
    put(name, {1, 1}, &v, desc, unit);
  }
  bool attr(hid_t o, const char* name, const char* text) {
    hid_t t = H5Tcopy(H5T_C_S1);
    H5Tset_size(t, std::strlen(text) + 1);
    hid_t s = H5Screate(H5S_SCALAR);
    hid_t a = H5Acreate2(o, name, t, s, H5P_DEFAULT, H5P_DEFAULT);
    bool r = a >= 0 && H5Awrite(a, t, text) >= 0;
    if (a >= 0) H5Aclose(a);
    H5Sclose(s);
    H5Tclose(t);
    return r;
  }
  void text(const std::string& name, const char* v) {
    if (!ok) return;
    hid_t t = H5Tcopy(H5T_C_S1);
    H5Tset_size(t, std::strlen(v));
    hid_t s = H5Screate(H5S_SCALAR);
    hid_t d = H5Dcreate2(f, name.c_str(), t, s, lcpl, H5P_DEFAULT, H5P_DEFAULT);
    ok = d >= 0 && H5Dwrite(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, v) >= 0;
    if (d >= 0) H5Dclose(d);
    H5Sclose(s);
    H5Tclose(t);
  }
};

// one complex table [6][nh][nw] / (rho g), e^{+i omega t}, with mag and phase
static void putForce(H5W* h, const std::string& g, const HydroCoef& c,
                     const std::vector<double>& re, const std::vector<double>& im,
                     const char* what) {
  size_t nw = c.omega.size(), nh = c.heading.size();
  std::vector<double> r(6 * nh * nw), i(r.size()), m(r.size()), p(r.size());
  for (size_t q = 0; q < nw; q++)
    for (size_t k = 0; k < nh; k++)
      for (int d = 0; d < 6; d++) {
        size_t s = (d * nh + k) * nw + q, o = 6 * (q * nh + k) + d;
        r[s] = re[o] / (c.rho * c.g);
        i[s] = -im[o] / (c.rho * c.g);
        m[s] = std::hypot(r[s], i[s]);
        p[s] = std::atan2(i[s], r[s]);
      }
  std::vector<hsize_t> dims = {6, nh, nw};
  std::string d = std::string(what) + " (normalized by rho*g)";
  h->put(g + "re", dims, r.data(), ("Real component of " + d).c_str(), "N");
  h->put(g + "im", dims, i.data(), ("Imaginary component of " + d).c_str(), "N");
  h->put(g + "mag", dims, m.data(), ("Magnitude of " + d).c_str(), "N");
  h->put(g + "phase", dims, p.data(), ("Phase angle of " + std::string(what)).c_str(), "rad");
}

static bool writeAll(H5W* h, const CoefFile& f) {
  const HydroCoef& c = f.c;
  size_t nw = c.omega.size(), nh = f.hasX ? c.nh() : 0;
  h->text("/bem_data/code", "mjbuoy");
  h->text("/body1/properties/name", "body");
  const std::string sp = "/simulation_parameters/";
  h->put1(sp + "scaled", 0, "", "");
  h->put1(sp + "g", c.g, "Gravitational acceleration", "m/s^2");
  h->put1(sp + "rho", c.rho, "Water density", "kg/m^3");
  std::vector<double> T(nw), deg(nh);
  for (size_t q = 0; q < nw; q++) T[q] = 2 * M_PI / c.omega[q];
  for (size_t k = 0; k < nh; k++) deg[k] = c.heading[k] * 180 / M_PI;
  h->put(sp + "T", {nw, 1}, T.data(), "Wave periods", "s");
  h->put(sp + "w", {nw, 1}, c.omega.data(), "Wave frequencies", "rad/s");
  if (c.depth > 0) h->put1(sp + "water_depth", c.depth, "Water depth", "m");
  else h->text(sp + "water_depth", "infinite");
  if (nh) h->put(sp + "wave_dir", {nh, 1}, deg.data(), "Wave direction", "deg");
  const std::string pr = "/body1/properties/";
  h->put1(pr + "body_number", 1, "Number of rigid body from the BEM simulation", "");
  double z3[3] = {0, 0, 0};
  h->put(pr + "cb", {1, 3}, z3, "Center of buoyancy", "m");
  h->put(pr + "cg", {1, 3}, f.cg, "Center of gravity", "m");
  h->put1(pr + "disp_vol", f.vol, "Displaced volume", "m^3");
  h->put1(pr + "dof", 6, "Degrees of freedom", "");
  h->put1(pr + "dof_start", 1, "Degrees of freedom", "");
  h->put1(pr + "dof_end", 6, "Degrees of freedom", "");
  const std::string hc = "/body1/hydro_coeffs/";
  std::vector<double> a(36 * nw), b(36 * nw), ai(36), C(36);
  for (size_t q = 0; q < nw; q++)
    for (int k = 0; k < 36; k++) {
      a[k * nw + q] = c.A[36 * q + k] / c.rho;
      b[k * nw + q] = c.B[36 * q + k] / (c.rho * c.omega[q]);
    }
  for (int k = 0; k < 36; k++) ai[k] = c.Ainf[k] / c.rho, C[k] = f.C[k] / (c.rho * c.g);
  if (f.hasC)
    h->put(hc + "linear_restoring_stiffness", {6, 6}, C.data(),
           "Hydrostatic stiffness matrix (normalized by rho*g)", "N/m");
  if (f.hasAinf)
    h->put(hc + "added_mass/inf_freq", {6, 6}, ai.data(),
           "Infinite frequency added mass (normalized by rho)", "kg");
  h->put(hc + "added_mass/all", {6, 6, nw}, a.data(), "Added mass (normalized by rho)", "kg");
  h->put(hc + "radiation_damping/all", {6, 6, nw}, b.data(),
         "Radiation damping (normalized by rho*w)", "N-s/m");
  if (nh) {
    std::vector<double> dr(c.Xre.size()), di(dr.size());
    for (size_t k = 0; k < dr.size(); k++) dr[k] = c.Xre[k] - c.FKre[k], di[k] = c.Xim[k] - c.FKim[k];
    putForce(h, hc + "excitation/", c, c.Xre, c.Xim, "excitation force");
    if (f.hasFK) {
      putForce(h, hc + "excitation/froude-krylov/", c, c.FKre, c.FKim, "Froude-Krylov force");
      putForce(h, hc + "excitation/scattering/", c, dr, di, "scattering force");
    }
  }
  return h->ok;
}

std::string writeBemio(const std::string& path, const CoefFile& f) {
  AtomicPath ap(path);
  H5E_auto2_t fn;
  void* data;
  H5Eget_auto2(H5E_DEFAULT, &fn, &data);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  hid_t h = H5Fcreate(ap.tmp().c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  bool ok = h >= 0;
  if (ok) {
    H5W w{h, H5Pcreate(H5P_LINK_CREATE)};
    H5Pset_create_intermediate_group(w.lcpl, 1);
    ok = writeAll(&w, f);
    H5Pclose(w.lcpl);
    ok = H5Fclose(h) >= 0 && ok;
  }
  H5Eset_auto2(H5E_DEFAULT, fn, data);
  if (!ok) return "cannot write the BEMIO file " + path + " (HDF5 error)";
  return ap.commit();
}

}  // namespace mjb
