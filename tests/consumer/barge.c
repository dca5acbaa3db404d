/* a program outside the project, built against an installed mjbuoy: the
   2 x 1 m box barge of 500 kg (models/barge.xml) floats at its draft
   T = m / (rho L B) = 500 / (1000 * 2 * 1) = 0.25 m (Archimedes) */
#include <math.h>
#include <stdio.h>

#include <mjbuoy/mjbuoy.h>

int main(int argc, char** argv) {
  char err[1000];
  if (argc != 2) {
    fprintf(stderr, "usage: %s barge.xml\n", argv[0]);
    return 2;
  }
  if (mjb_version() != MJBUOY_VERSION) {
    fprintf(stderr, "FAIL header %d, library %d\n", MJBUOY_VERSION, mjb_version());
    return 1;
  }
  mjModel* m = mj_loadXML(argv[1], NULL, err, sizeof(err));
  if (!m) {
    fprintf(stderr, "FAIL %s\n", err);
    return 1;
  }
  mjbBuoy* b = mjb_attach(m, "cpu", err, sizeof(err));
  if (!b) {
    fprintf(stderr, "FAIL %s\n", err);
    return 1;
  }
  mjData* d = mj_makeData(m);
  /* 30 s: the heave settles within 20 s (half-critical damping); mean of the
     last 10 s */
  long n = (long)(30 / m->opt.timestep), n0 = (long)(20 / m->opt.timestep);
  double z = 0;
  for (long i = 0; i < n; i++) {
    mj_step(m, d);
    if (i >= n0) z += d->qpos[2] / (n - n0);
  }
  /* the box's half-height is 0.25 m: draft = 0.25 - z of its centre */
  double draft = 0.25 - z, expect = 500 / (1000 * 2.0 * 1.0);
  int ok = fabs(draft - expect) < 1e-3;
  printf("mjbuoy %s (%d): barge draft %.5f m, expected %.5f m: %s\n", mjb_versionString(),
         mjb_version(), draft, expect, ok ? "ok" : "FAIL");
  mj_deleteData(d);
  mjb_detach(b);
  mj_deleteModel(m);
  return ok ? 0 : 1;
}
