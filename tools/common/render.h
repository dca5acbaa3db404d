// render: headless pictures of an mjbuoy scene for mjbuoy-sim (--render,
// --snapshot, --show-forces, --show-wet).
//
// MuJoCo's own renderer (mjr_render) draws the model into its offscreen
// buffer, sized to the request, on a GL 4.5 compatibility-profile context of
// our own on Mesa's surfaceless EGL platform (no window, no X server). Into
// the same framebuffer, seadraw.h (shared with mjbuoy-view) then draws the
// sky, the sea from the exact surface, and optionally the wet part of each
// hull; the model needs no visual elements of its own (seadraw.h lists the
// mjbuoy-sim.sea.* entries that override the sea's look).
// Without a camera name, a free camera frames all hull bodies and follows
// them. Frames go to the ffmpeg program through a pipe (H.264 MP4), stills
// to PNG through libpng.
#ifndef MJBUOY_TOOLS_RENDER_H_
#define MJBUOY_TOOLS_RENDER_H_

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "mjbuoy.h"

namespace mjbsim {

struct RenderOptions {
  int width = 1280, height = 720;
  std::string camera;       // model camera name; empty: free camera framing the hulls
  bool showForces = false;  // per-body force arrows (mjb_wrench)
  bool showWet = false;     // the wet part of each hull in a colour of its own
};

class Renderer {
 public:
  // a renderer for m (copied; offscreen buffer resized to the request);
  // nullptr with the reason in err
  static std::unique_ptr<Renderer> create(const mjModel* m, const mjbBuoy* b,
                                          const RenderOptions& o, std::string* err);
  ~Renderer();

  // draw d; rgb gets width*height*3 bytes, bottom row first (OpenGL order)
  bool render(const mjData* d, std::vector<unsigned char>* rgb, std::string* err);

  // the camera of the last picture, one line (free camera: lookat, distance,
  // azimuth, elevation, fovy)
  std::string describeCamera() const;

  int width() const;
  int height() const;

  struct Impl;

 private:
  explicit Renderer(Impl* p) : p_(p) {}
  Impl* p_;
};

// H.264 MP4 through the ffmpeg program; its stderr goes to a temporary log
// in $TMPDIR, whose last lines are the reason given when it fails
class VideoWriter {
 public:
  ~VideoWriter();
  // checks that ffmpeg is on PATH, then starts it writing file (the
  // caller's temporary file); name is the output in messages. SIGPIPE must
  // be ignored: a failing ffmpeg then makes write() fail with EPIPE
  bool open(const std::string& file, const std::string& name, int width, int height, double fps,
            std::string* err);
  // one frame, bottom row first
  bool write(const std::vector<unsigned char>& rgb, std::string* err);
  // waits for ffmpeg; false with its complaint if it failed
  bool close(std::string* err);
  int frames() const { return frames_; }

 private:
  FILE* pipe_ = nullptr;
  std::string path_, name_, log_;
  int width_ = 0, height_ = 0, frames_ = 0;
};

// the directory on PATH holding an executable `name`, or ""
std::string findProgram(const std::string& name);

// PNG through libpng into f (name for messages); rgb bottom row first, so
// rows are flipped. f stays open: the caller checks and closes it
bool writePng(FILE* f, const std::string& name, const std::vector<unsigned char>& rgb,
              int width, int height, std::string* err);

// shell-quote s for popen
std::string shellQuote(const std::string& s);

}  // namespace mjbsim

#endif  // MJBUOY_TOOLS_RENDER_H_
