// radconfig: the mjbuoy.radiation* MJCF entries (docs/mjcf.md section
// "Radiation"), called from parseConfig
#ifndef MJBUOY_RADCONFIG_H_
#define MJBUOY_RADCONFIG_H_

#include <string>
#include <vector>

#include <mujoco/mujoco.h>

namespace mjb {

// the default fraction of critical roll damping (mjbuoy.radiation.rollzeta):
// viscous roll damping of ships, 5 to 10% of critical in total, is mostly
// eddy, friction and bilge-keel damping that potential flow leaves out
// (Himeno 1981; ITTC 7.5-02-07-04.5; docs/physics.md section 14). The
// upper end: the eddy part is quadratic, so at the 20 to 40 deg rolls of
// steep seas the equivalent linear damping is above its small-roll value
const double kRollZeta = 0.10;

struct RadConfig {
  bool on = true;               // mjbuoy.radiation: on (default) or off
  bool given = false;           // mjbuoy.radiation was in the model
  std::vector<int> onBody;      // mjbuoy.radiation.body.<body>: on / off overrides
  std::vector<int> offBody;
  double omega[3] = {0, 0, 0};  // wmin, wmax [rad/s], count; count 0: defaultOmega (radattach.h)
  int refine = 0;               // hullPanels refine level 0..4
  bool refineGiven = false;     // mjbuoy.radiation.refine was in the model
  int panels = 400;             // wet panel budget (kDefaultPanels): a finer hull is coarsened; 0: never
  bool panelsGiven = false;     // mjbuoy.radiation.panels was in the model
  // the budget in force: the given one; none (0) when refine is given
  // alone, since a hull refined on purpose is never coarsened back; else
  // the default
  int budget() const { return panelsGiven ? panels : refineGiven ? 0 : panels; }
  bool lid = true;              // interior lid against irregular frequencies
  bool diffraction = true;      // diffraction excitation (docs/physics.md section 15)
  bool drift = true;            // mean and slow wave drift, with diffraction (section 18)
  double memory = 0;            // memory length [s]; 0: automatic
  bool conv = false;            // mjbuoy.radiation.memorymodel: statespace (default) or convolution
  bool ssAsked = false;         // memorymodel = statespace given explicitly: warn on a fallback
  std::string cache;            // mjbuoy.radiation.cache: directory or "off"; "": default
  // mjbuoy.radiation.rolldamping: viscous roll damping about each radiating
  // group's body x axis, linear [N m s/rad] and quadratic [N m s^2/rad^2]
  double roll[2] = {0, 0};
  bool rollGiven = false;       // mjbuoy.radiation.rolldamping was in the model
  // mjbuoy.radiation.rollzeta: a further linear roll damping, this fraction
  // of each radiating group's critical roll damping (docs/physics.md
  // section 14, "Viscous roll damping"); kRollZeta when the model gives
  // neither it nor rolldamping, 0 when it gives rolldamping only
  double zeta = kRollZeta;
  bool zetaGiven = false;       // mjbuoy.radiation.rollzeta was in the model
  // mjbuoy.radiation.entry: the water's momentum taken up as the immersion
  // factor rises (docs/physics.md section 14, "Water entry"); on by
  // default: without it every entry creates (1/2) ds nu^T A_inf nu of energy
  bool entry = true;
  // mjbuoy.radiation.speed: Salvesen-Tuck-Faltinsen's forward-speed memory
  // terms (docs/physics.md section 14, "Forward speed"): 0 off, 1 auto (the
  // default: hulls slender along x, the bodies strip theory is for), 2 on
  int speed = 1;
  // mjbuoy.radiation.file.<body>: the body's coefficients read from a file
  // of another tool instead of the panel solver (docs/interchange.md), with
  // mjbuoy.radiation.fileorigin.<body> (the file's origin in the body frame
  // [m]) and mjbuoy.radiation.ulen.<body> (WAMIT's length scale [m])
  struct File {
    int body = -1;
    std::string path;
    double origin[3] = {0, 0, 0};
    double ulen = 1;
  };
  std::vector<File> file;
  // mjbuoy.radiation.group: groups of body names solved together
  // (hydrodynamic interaction, docs/physics.md section 14, "Interaction"),
  // as given; checked at attach (radgroup.h, groupBodies)
  std::vector<std::vector<std::string>> group;
  bool radiates(int body) const;
  // whether the rigid group of weld root `root` radiates: an override
  // naming the root or any of its hull bodies (hullBody, one per hull)
  // wins over `on` (off over on); a group that cannot move (groupMoves)
  // never radiates; `on` covers free and jointed groups alike
  bool groupRadiates(const mjModel* m, const std::vector<int>& hullBody, int root) const;
};

// whether the rigid group of weld root `root` can move (a joint between it
// and the world, not mocap): static and mocap hulls never radiate
bool groupMoves(const mjModel* m, int root);

// whether the key after "mjbuoy." is one of these entries
bool isRadEntry(const char* key);

// read them into r; "" or the first error
std::string parseRadConfig(const mjModel* m, RadConfig* r);

}  // namespace mjb

#endif  // MJBUOY_RADCONFIG_H_
