// seadraw: what mjbuoy adds to MuJoCo's picture of a scene, shared by
// mjbuoy-sim's offscreen renderer (render.cc) and the interactive viewer
// mjbuoy-view (view.cc), so both show the same sea.
//
// After mjr_render has drawn the model, SeaPainter::draw draws into the same
// framebuffer, with MuJoCo's projection and depth buffer: a sky where nothing
// was drawn, optionally the wet part of each hull (its triangles below the
// exact surface, cut at the surface, in a colour of their own), and the sea:
// a graded triangle grid around the camera's point of interest with heights
// from mjb_seaHeight (the exact surface the physics uses: Gerstner and
// linear components), a fixed 97 x 97 vertices whose spacing grows
// outwards (its cost: components x vertices a frame, whatever the pixels),
// semi-transparent, so the wet part of each hull shows through it. Two
// optional <custom> entries override the sea (mjbuoy-sim.* entries are not
// mjbuoy.* entries, so the library ignores them):
//   <numeric name="mjbuoy-sim.sea.rgba" data="r g b a"/>   colour, opacity
//   <numeric name="mjbuoy-sim.sea.extent" data="R"/>      half-size [m]
#ifndef MJBUOY_TOOLS_SEADRAW_H_
#define MJBUOY_TOOLS_SEADRAW_H_

#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "mjbuoy.h"

namespace mjbsim {

// colour of the wet part of the hulls (magenta: neither sea nor a usual hull colour)
extern const float kWetRgba[4];

class SeaPainter {
 public:
  // reads the mjbuoy-sim.sea.* entries and the hull meshes of m; extends
  // m's far plane to the sea's edge (m is the caller's copy); false with
  // the reason in err
  bool init(mjModel* m, const mjbBuoy* b, std::string* err);

  // copies what draw() needs from d (time, hull body poses); call while d
  // is not being stepped
  void capture(const mjData* d);

  // after mjr_render into viewport vp of the current framebuffer: sky,
  // wet hull parts (if wet), sea; scn's camera, cam for the grid centre
  void draw(const mjvScene& scn, const mjvCamera& cam, mjrRect vp, bool wet);

 private:
  void drawSky(const mjvGLCamera& c, double halfw);
  void drawWet();
  void drawSea(const mjvGLCamera& c, const mjvCamera& cam, double halfw);
  void markVisible(const mjvGLCamera& c, double halfw, double cx, double cy, int n);

  const mjModel* m_ = nullptr;
  const mjbBuoy* b_ = nullptr;
  float sea_[4];
  double extent_ = 0;  // sea half-size [m]; 0: from the camera distance
  bool skybox_ = false;
  double time_ = 0;
  // hulls: body-frame meshes of every hull geom, and the poses of their bodies
  struct Hull {
    int body;
    std::vector<double> v;  // body-frame vertices, 3 each [m]
    std::vector<int> f;     // triangles, 3 vertex indices each, outward
  };
  std::vector<Hull> hulls_;
  std::vector<double> pose_;          // per hull: body xpos (3) and xmat (9)
  std::vector<double> world_, height_;  // scratch: world vertices, height above the sea
  std::vector<double> u_;              // scratch: sea grid axis
  std::vector<float> z_, col_;         // scratch: sea grid heights and colours
  std::vector<float> xyz_;             // scratch: sea grid vertices
  std::vector<char> vis_;              // scratch: sea grid vertices in view (their heights)
  double level_ = 0, amp_ = 0;         // mean level, sum of amplitudes: the surface's band [m]
  std::vector<unsigned> strip_;        // sea grid strips' vertex indices, row by row
  static const int kHalf = 48;         // sea grid vertices each side of the centre
};

// one arrow per body that mjbuoy pushes on, added to scn: from the centre
// of mass along the force; the body's own weight is as long as its bounding
// radius
void addForceArrows(const mjModel* m, const mjbBuoy* b, const mjData* d, mjvScene* scn);

// the mooring lines of d (mjb_lineNodes) added to scn: a dark capsule per
// segment, as thick as a thousandth of the line's length (at least 5 cm)
// so a chain shows at any zoom; and the seabed when the model has one
// (mjb_seabed): a sand-coloured slab with a grid under the lines, 200 m
// across the origin without lines
void addLines(const mjbBuoy* b, const mjData* d, mjvScene* scn);

// a free camera that frames all hull bodies from the south, 25 degrees
// above the horizon, and follows them smoothly (update on every picture)
class HullFramer {
 public:
  void update(const mjModel* m, const mjbBuoy* b, const mjData* d, double aspect,
              mjvCamera* cam);
  const std::vector<int>& bodies() const { return bodies_; }

 private:
  void choose(const mjModel* m, const mjbBuoy* b, const mjData* d);
  std::vector<int> bodies_;
  bool framed_ = false;
  double lastTime_ = 0;
};

}  // namespace mjbsim

#endif  // MJBUOY_TOOLS_SEADRAW_H_
