// coefexport: a body's coefficients for a file (coefexport.h)
#include "api/coefexport.h"

#include "radiation/coefxform.h"

namespace mjb {

std::string exportCoef(const Buoy& B, int body, CoefFile* f) {
  const HydroCoef* c = nullptr;
  for (const auto& p : B.coef)
    if (p.first == body) c = &p.second;
  if (!c) return "the body has no radiation coefficients (radiation off for it)";
  *f = CoefFile();
  f->c = *c;
  f->hasAinf = true;
  for (const RadBody& x : B.rad.rb)
    if (x.body == body) f->vol = x.veq;
  for (const DiffBody& db : B.diff.db) {
    if (db.body != body) continue;
    // X, FK about the COM in world axes at qpos0 to body axes: R0's
    // columns are the body's axes in the world (coefxform.h)
    HydroCoef x = db.c;
    x.A.assign(36 * x.omega.size(), 0);
    x.B = x.A;
    std::string e = coefTransform(&x, x.ref, db.R0, x.ref);
    if (!e.empty()) return e;
    f->c.heading = x.heading;
    f->c.Xre = x.Xre;
    f->c.Xim = x.Xim;
    f->c.FKre = x.FKre;
    f->c.FKim = x.FKim;
    f->hasX = f->hasFK = true;
  }
  for (int k = 0; k < 3; k++) f->c.ref[k] = 0;  // the file's origin: the COM
  return "";
}

}  // namespace mjb
