// glprog: compute shader programs built from the shaders embedded at build
// time (shaders/*.comp, see cmake/embed_shaders.cmake); no file is read at
// run time. Build programs once, when attaching, never per step.
#ifndef MJBUOY_GLPROG_H_
#define MJBUOY_GLPROG_H_

#include <string>

#include <glad/gl.h>

namespace mjb {

// GLSL of shaders/NAME (e.g. "selftest.comp") with its includes pasted in;
// null if there is no such shader. files (optional) gets which file each
// source string number of the driver's log is, e.g.
// "0 shaders/selftest.comp, 1 shaders/shared.h". Generated code.
const char* shaderSource(const char* name, const char** files = nullptr);

// name of the i-th embedded shader, null past the last. Generated code.
const char* shaderName(int i);

// compile and link shaders/NAME as a compute program, with gl's context
// current: the program id, or 0 with the reason in err, which names the
// file and holds the driver's log; defines are lines put after its #version
GLuint glProgram(const GladGLContext& gl, const char* name, std::string* err,
                 const std::string& defines = "");

// the same from source text; label names it in errors
GLuint glProgramSource(const GladGLContext& gl, const char* label, const char* src,
                       std::string* err);

}  // namespace mjb

#endif  // MJBUOY_GLPROG_H_
