// coefio_netcdf: Capytaine's NetCDF dataset (coefio.h; docs/interchange.md).
// Capytaine (Ancellin and Dias 2019; capytaine.io, "Outputs") saves with its
// complex values separated: variables added_mass and radiation_damping over
// (omega, radiating_dof, influenced_dof), diffraction_force and
// Froude_Krylov_force over (omega, wave_direction, influenced_dof, complex),
// complex = ("re", "im"); SI units, time dependence e^{-i omega t} as
// mjbuoy's, its exciting force the sum of the two forces. The dimensions
// are found by name, in any order
#include <netcdf.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "radiation/coefio.h"
#include "util/fmt.h"

namespace mjb {

static const char* kDofName[6] = {"Surge", "Sway", "Heave", "Roll", "Pitch", "Yaw"};

static std::string ncErr(const std::string& path, const std::string& what, int st) {
  return "Capytaine file " + path + ": " + what + ": " + nc_strerror(st);
}

// a variable's dimension names, sizes and values (as double)
struct NcVar {
  std::vector<std::string> dim;
  std::vector<size_t> len;
  std::vector<double> v;
  // the axis of dimension name, -1 if none
  int axis(const char* name) const {
    for (size_t i = 0; i < dim.size(); i++)
      if (dim[i] == name) return (int)i;
    return -1;
  }
};

// read variable name; "" or the error; *found false if absent
static std::string ncRead(int id, const std::string& path, const char* name, NcVar* x,
                          bool* found) {
  int vid, nd, dims[NC_MAX_VAR_DIMS];
  *found = nc_inq_varid(id, name, &vid) == NC_NOERR;
  if (!*found) return "";
  int st = nc_inq_varndims(id, vid, &nd);
  if (st == NC_NOERR) st = nc_inq_vardimid(id, vid, dims);
  size_t n = 1;
  for (int i = 0; st == NC_NOERR && i < nd; i++) {
    char dn[NC_MAX_NAME + 1];
    size_t l;
    st = nc_inq_dim(id, dims[i], dn, &l);
    x->dim.push_back(dn);
    x->len.push_back(l);
    n *= l;
  }
  if (st == NC_NOERR && n > (size_t(1) << 28)) return "Capytaine file " + path + ": " + name +
                                                      " is too large";
  x->v.resize(n);
  if (st == NC_NOERR && n) st = nc_get_var_double(id, vid, x->v.data());
  if (st != NC_NOERR) return ncErr(path, std::string("variable ") + name, st);
  return "";
}

// the strings of a 1-D coordinate (NC_STRING or a 2-D char array)
static std::vector<std::string> ncStrings(int id, const char* name) {
  std::vector<std::string> out;
  int vid, nd, dims[NC_MAX_VAR_DIMS];
  nc_type t;
  if (nc_inq_varid(id, name, &vid) || nc_inq_vartype(id, vid, &t) || nc_inq_varndims(id, vid, &nd) ||
      nc_inq_vardimid(id, vid, dims))
    return out;
  size_t n = 0, w = 0;
  if (nd < 1 || nc_inq_dimlen(id, dims[0], &n) || n > 4096) return out;
  if (t == NC_STRING && nd == 1) {
    std::vector<char*> s(n);
    if (nc_get_var_string(id, vid, s.data())) return out;
    for (char* p : s) out.push_back(p ? p : "");
    nc_free_string(n, s.data());
  } else if (t == NC_CHAR && nd == 2 && !nc_inq_dimlen(id, dims[1], &w) && w < 4096) {
    std::vector<char> s(n * w);
    if (nc_get_var_text(id, vid, s.data())) return out;
    for (size_t i = 0; i < n; i++) out.push_back(std::string(&s[i * w], strnlen(&s[i * w], w)));
  }
  return out;
}

// mode 0..5 of a dof name ("Heave", "body__heave"), -1 if none
static int dofIndex(const std::string& s) {
  std::string l;
  for (char c : s) l += (char)std::tolower((unsigned char)c);
  for (int i = 0; i < 6; i++) {
    std::string d = kDofName[i];
    for (char& c : d) c = (char)std::tolower((unsigned char)c);
    if (l.size() >= d.size() && !l.compare(l.size() - d.size(), d.size(), d)) return i;
  }
  return -1;
}

// the modes of a dof coordinate of length n: its names, else 0..n-1
static std::string dofMap(int id, const std::string& path, const char* name, size_t n,
                          std::vector<int>* m) {
  std::vector<std::string> s = ncStrings(id, name);
  m->clear();
  for (size_t i = 0; i < n; i++) {
    int k = i < s.size() ? dofIndex(s[i]) : (s.empty() && n == 6 ? (int)i : -1);
    if (k < 0)
      return "Capytaine file " + path + ": " + name + " " + std::to_string(i + 1) + " (\"" +
             (i < s.size() ? s[i] : "") + "\") is not one of Surge, Sway, Heave, Roll, Pitch, "
             "Yaw; mjbuoy reads one rigid body's dofs";
    m->push_back(k);
  }
  return "";
}

// flat index of v at the coordinates idx (one per axis, by name order ax)
static size_t flat(const NcVar& v, const int* ax, const size_t* idx, int n) {
  std::vector<size_t> at(v.dim.size(), 0);
  for (int k = 0; k < n; k++) at[ax[k]] = idx[k];
  size_t f = 0;
  for (size_t d = 0; d < v.dim.size(); d++) f = f * v.len[d] + at[d];
  return f;
}

// the variables of a Capytaine dataset that mjbuoy reads
struct CapyVars {
  NcVar w, am, bd, dif, fk, hd;
  bool gotD = false, gotF = false;  // diffraction_force, Froude_Krylov_force found
  bool gotH = false;                // wave_direction found
};

// the dataset's variables into v, and rho, g and the depth (m) into c; "" or the error
static std::string readVars(int id, const std::string& path, CapyVars* v, HydroCoef* c) {
  bool got;
  std::string e = ncRead(id, path, "omega", &v->w, &got);
  if (e.empty() && !got)
    return "Capytaine file " + path + " has no omega coordinate (save the dataset with "
           "frequencies as omega)";
  if (e.empty()) e = ncRead(id, path, "added_mass", &v->am, &got);
  if (e.empty() && got) e = ncRead(id, path, "radiation_damping", &v->bd, &got);
  if (e.empty() && !got)
    return "Capytaine file " + path + " has no added_mass or radiation_damping";
  if (e.empty()) e = ncRead(id, path, "diffraction_force", &v->dif, &v->gotD);
  if (e.empty()) e = ncRead(id, path, "Froude_Krylov_force", &v->fk, &v->gotF);
  if (e.empty()) e = ncRead(id, path, "wave_direction", &v->hd, &v->gotH);
  if (!e.empty()) return e;
  for (const char* s : {"rho", "g"}) {
    NcVar x;
    e = ncRead(id, path, s, &x, &got);
    if (!e.empty()) return e;
    if (got && x.v.size() == 1) (*s == 'r' ? c->rho : c->g) = x.v[0];
  }
  NcVar dp;
  e = ncRead(id, path, "water_depth", &dp, &got);
  if (got && dp.v.size() == 1 && std::isfinite(dp.v[0])) c->depth = dp.v[0];
  return "";
}

// added mass and damping over the finite frequencies > 0 (rows, ascending) and A_inf from an
// infinite one; mr, mi: the modes of radiating_dof and influenced_dof
static std::string readRadiation(int id, const std::string& path, const CapyVars& v,
                                 CoefFile* f, std::vector<int>* mr, std::vector<int>* mi,
                                 std::vector<size_t>* rows) {
  HydroCoef& c = f->c;
  const NcVar &w = v.w, &am = v.am, &bd = v.bd;
  int rw = am.axis("omega"), rr = am.axis("radiating_dof"), ri = am.axis("influenced_dof");
  if (rw < 0 || rr < 0 || ri < 0 || am.dim.size() != 3 || bd.dim != am.dim || bd.len != am.len)
    return "Capytaine file " + path + ": added_mass and radiation_damping must be over omega, "
           "radiating_dof and influenced_dof";
  std::string e = dofMap(id, path, "radiating_dof", am.len[rr], mr);
  if (e.empty()) e = dofMap(id, path, "influenced_dof", am.len[ri], mi);
  if (!e.empty()) return e;
  // frequencies: 0 left out, infinity is A_inf
  for (size_t k = 0; k < w.v.size(); k++) {
    if (std::isinf(w.v[k])) {
      for (size_t a = 0; a < mr->size(); a++)
        for (size_t b = 0; b < mi->size(); b++) {
          int ax[3] = {rw, rr, ri};
          size_t idx[3] = {k, a, b};
          c.Ainf[6 * (*mi)[b] + (*mr)[a]] = am.v[flat(am, ax, idx, 3)];
        }
      f->hasAinf = true;
    } else if (w.v[k] > 0) {
      rows->push_back(k);
    }
  }
  std::sort(rows->begin(), rows->end(), [&](size_t a, size_t b) { return w.v[a] < w.v[b]; });
  for (size_t r : *rows) c.omega.push_back(w.v[r]);
  c.A.assign(36 * rows->size(), 0);
  c.B.assign(36 * rows->size(), 0);
  for (size_t q = 0; q < rows->size(); q++)
    for (size_t a = 0; a < mr->size(); a++)
      for (size_t b = 0; b < mi->size(); b++) {
        int ax[3] = {rw, rr, ri};
        size_t idx[3] = {(*rows)[q], a, b};
        size_t s = flat(am, ax, idx, 3);
        c.A[36 * q + 6 * (*mi)[b] + (*mr)[a]] = am.v[s];
        c.B[36 * q + 6 * (*mi)[b] + (*mr)[a]] = bd.v[s];
      }
  return "";
}

// the exciting force X = F_K + F_D and its Froude-Krylov part over rows, headings and mi
static std::string readExciting(int id, const std::string& path, const CapyVars& v,
                                const std::vector<size_t>& rows, const std::vector<int>& mi,
                                CoefFile* f) {
  HydroCoef& c = f->c;
  if (!v.gotD || !v.gotF || !v.gotH)
    return "Capytaine file " + path + ": an exciting force needs diffraction_force, "
           "Froude_Krylov_force and wave_direction together";
  std::vector<std::string> cx = ncStrings(id, "complex");
  int re = 0, im = 1;
  if (cx.size() == 2 && cx[0] == "im" && cx[1] == "re") re = 1, im = 0;
  for (const NcVar* x : {&v.dif, &v.fk}) {
    int xw = x->axis("omega"), xh = x->axis("wave_direction"), xi = x->axis("influenced_dof"),
        xc = x->axis("complex");
    if (xw < 0 || xh < 0 || xi < 0 || xc < 0 || x->dim.size() != 4 || x->len[xi] != mi.size() ||
        x->len[xc] != 2 || x->len[xw] != v.w.v.size())
      return "Capytaine file " + path + ": diffraction_force and Froude_Krylov_force must be "
             "over omega, wave_direction, influenced_dof and complex (saved with complex "
             "values separated)";
  }
  c.heading = v.hd.v;
  size_t nh = v.hd.v.size(), nx = 6 * rows.size() * nh;
  for (auto* x : {&c.Xre, &c.Xim, &c.FKre, &c.FKim}) x->assign(nx, 0);
  for (size_t q = 0; q < rows.size(); q++)
    for (size_t h = 0; h < nh; h++)
      for (size_t b = 0; b < mi.size(); b++) {
        size_t o = 6 * (q * nh + h) + mi[b];
        double part[2][2];
        const NcVar* vs[2] = {&v.fk, &v.dif};
        for (int s = 0; s < 2; s++) {
          const NcVar& x = *vs[s];
          int ax[4] = {x.axis("omega"), x.axis("wave_direction"), x.axis("influenced_dof"),
                       x.axis("complex")};
          for (int k = 0; k < 2; k++) {
            size_t idx[4] = {rows[q], h, b, (size_t)(k ? im : re)};
            part[s][k] = x.v[flat(x, ax, idx, 4)];
          }
        }
        c.FKre[o] = part[0][0], c.FKim[o] = part[0][1];
        c.Xre[o] = part[0][0] + part[1][0], c.Xim[o] = part[0][1] + part[1][1];
      }
  f->hasX = f->hasFK = true;
  return "";
}

// the hydrostatic stiffness C (N/m, N, N m) if the dataset has one over mi and mr
static std::string readStiffness(int id, const std::string& path, const std::vector<int>& mr,
                                 const std::vector<int>& mi, CoefFile* f) {
  NcVar hs;
  bool got;
  std::string e = ncRead(id, path, "hydrostatic_stiffness", &hs, &got);
  if (e.empty() && got && hs.v.size() == mi.size() * mr.size()) {
    int a0 = hs.axis("influenced_dof"), a1 = hs.axis("radiating_dof");
    for (size_t a = 0; a0 >= 0 && a1 >= 0 && a < mi.size(); a++)
      for (size_t b = 0; b < mr.size(); b++) {
        int ax[2] = {a0, a1};
        size_t idx[2] = {a, b};
        f->C[6 * mi[a] + mr[b]] = hs.v[flat(hs, ax, idx, 2)];
      }
    f->hasC = a0 >= 0 && a1 >= 0;
  }
  return e;
}

static std::string readAll(int id, const std::string& path, CoefFile* f) {
  CapyVars v;
  std::string e = readVars(id, path, &v, &f->c);
  if (!e.empty()) return e;
  std::vector<int> mr, mi;
  std::vector<size_t> rows;
  e = readRadiation(id, path, v, f, &mr, &mi, &rows);
  if (!e.empty()) return e;
  if (!v.gotD && !v.gotF) return "";
  e = readExciting(id, path, v, rows, mi, f);
  if (!e.empty()) return e;
  return readStiffness(id, path, mr, mi, f);
}

std::string readCapytaine(const std::string& path, CoefFile* f) {
  int id, st = nc_open(path.c_str(), NC_NOWRITE, &id);
  if (st != NC_NOERR) return ncErr(path, "cannot open", st);
  std::string e = readAll(id, path, f);
  nc_close(id);
  return e;
}

// the variable ids of a dataset being written (-1: not in it)
struct NcIds {
  int vw, vh = -1, vr, vi, vc = -1, va, vb, vd = -1, vf = -1, vg, vrho, vdep, vs = -1;
};

#define NC(x) \
  if ((st = (x)) != NC_NOERR) return st

// the global attributes, dimensions and variables of f's dataset (define mode), ids into v
static int defineDataset(int id, const CoefFile& f, size_t nw, size_t nh, NcIds* v) {
  int dw, dh = -1, dr, di, dc = -1, st;
  NC(nc_put_att_text(id, NC_GLOBAL, "source", 6, "mjbuoy"));
  const char* conv = "Capytaine's conventions: SI units, time dependence e^{-i omega t}, "
                     "forces about the body frame's origin";
  NC(nc_put_att_text(id, NC_GLOBAL, "conventions", std::strlen(conv), conv));
  NC(nc_def_dim(id, "omega", nw, &dw));
  NC(nc_def_dim(id, "radiating_dof", 6, &dr));
  NC(nc_def_dim(id, "influenced_dof", 6, &di));
  NC(nc_def_var(id, "omega", NC_DOUBLE, 1, &dw, &v->vw));
  NC(nc_def_var(id, "radiating_dof", NC_STRING, 1, &dr, &v->vr));
  NC(nc_def_var(id, "influenced_dof", NC_STRING, 1, &di, &v->vi));
  int d3[3] = {dw, dr, di};
  NC(nc_def_var(id, "added_mass", NC_DOUBLE, 3, d3, &v->va));
  NC(nc_def_var(id, "radiation_damping", NC_DOUBLE, 3, d3, &v->vb));
  if (nh) {
    NC(nc_def_dim(id, "wave_direction", nh, &dh));
    NC(nc_def_dim(id, "complex", 2, &dc));
    NC(nc_def_var(id, "wave_direction", NC_DOUBLE, 1, &dh, &v->vh));
    NC(nc_def_var(id, "complex", NC_STRING, 1, &dc, &v->vc));
    int d4[4] = {dw, dh, di, dc};
    NC(nc_def_var(id, "diffraction_force", NC_DOUBLE, 4, d4, &v->vd));
    NC(nc_def_var(id, "Froude_Krylov_force", NC_DOUBLE, 4, d4, &v->vf));
  }
  if (f.hasC) {
    int d2[2] = {di, dr};
    NC(nc_def_var(id, "hydrostatic_stiffness", NC_DOUBLE, 2, d2, &v->vs));
  }
  NC(nc_def_var(id, "g", NC_DOUBLE, 0, nullptr, &v->vg));
  NC(nc_def_var(id, "rho", NC_DOUBLE, 0, nullptr, &v->vrho));
  NC(nc_def_var(id, "water_depth", NC_DOUBLE, 0, nullptr, &v->vdep));
  NC(nc_enddef(id));
  return NC_NOERR;
}

// omega (infinity last for A_inf), the dof names, added mass and damping over nw frequencies
static int putRadiation(int id, const CoefFile& f, size_t nw, const NcIds& v) {
  const HydroCoef& c = f.c;
  int st;
  std::vector<double> w = c.omega, a, b;
  if (f.hasAinf) w.push_back(std::numeric_limits<double>::infinity());
  NC(nc_put_var_double(id, v.vw, w.data()));
  const char* dn[6];
  for (int i = 0; i < 6; i++) dn[i] = kDofName[i];
  NC(nc_put_var_string(id, v.vr, dn));
  NC(nc_put_var_string(id, v.vi, dn));
  // (omega, radiating j, influenced i) = mjbuoy's [6 i + j]
  for (size_t q = 0; q < nw; q++)
    for (int j = 0; j < 6; j++)
      for (int i = 0; i < 6; i++) {
        bool inf = q == c.omega.size();
        a.push_back(inf ? c.Ainf[6 * i + j] : c.A[36 * q + 6 * i + j]);
        b.push_back(inf ? 0 : c.B[36 * q + 6 * i + j]);
      }
  NC(nc_put_var_double(id, v.va, a.data()));
  NC(nc_put_var_double(id, v.vb, b.data()));
  return NC_NOERR;
}

// the headings and the exciting force split as Capytaine's: diffraction X - F_K and
// Froude-Krylov F_K, NaN at the infinite frequency
static int putExciting(int id, const HydroCoef& c, size_t nw, size_t nh, const NcIds& v) {
  int st;
  NC(nc_put_var_double(id, v.vh, c.heading.data()));
  const char* ri[2] = {"re", "im"};
  NC(nc_put_var_string(id, v.vc, ri));
  std::vector<double> xd, xf;
  for (size_t q = 0; q < nw; q++)
    for (size_t h = 0; h < nh; h++)
      for (int i = 0; i < 6; i++) {
        if (q == c.omega.size()) {  // no exciting force at infinite frequency
          for (auto* x : {&xd, &xd, &xf, &xf}) x->push_back(NAN);
          continue;
        }
        size_t o = 6 * (q * nh + h) + i;
        xd.push_back(c.Xre[o] - c.FKre[o]);
        xd.push_back(c.Xim[o] - c.FKim[o]);
        xf.push_back(c.FKre[o]);
        xf.push_back(c.FKim[o]);
      }
  NC(nc_put_var_double(id, v.vd, xd.data()));
  NC(nc_put_var_double(id, v.vf, xf.data()));
  return NC_NOERR;
}

// the dataset of f into the open file id
static int writeAll(int id, const CoefFile& f) {
  const HydroCoef& c = f.c;
  size_t nw = c.omega.size() + (f.hasAinf ? 1 : 0), nh = f.hasX ? c.nh() : 0;
  int st;
  NcIds v;
  NC(defineDataset(id, f, nw, nh, &v));
  NC(putRadiation(id, f, nw, v));
  if (nh) NC(putExciting(id, c, nw, nh, v));
  if (f.hasC) NC(nc_put_var_double(id, v.vs, f.C));
  double inf = std::numeric_limits<double>::infinity();
  NC(nc_put_var_double(id, v.vg, &c.g));
  NC(nc_put_var_double(id, v.vrho, &c.rho));
  NC(nc_put_var_double(id, v.vdep, c.depth > 0 ? &c.depth : &inf));
  return NC_NOERR;
}

#undef NC

std::string writeCapytaine(const std::string& path, const CoefFile& f) {
  AtomicPath ap(path);
  int id, st = nc_create(ap.tmp().c_str(), NC_NETCDF4 | NC_CLOBBER, &id);
  if (st != NC_NOERR) return ncErr(path, "cannot write", st);
  st = writeAll(id, f);
  int cl = nc_close(id);
  if (st == NC_NOERR) st = cl;
  if (st != NC_NOERR) return ncErr(path, "cannot write", st);
  return ap.commit();
}

}  // namespace mjb
