// glprog: compile and link compute programs
#include "gl/glprog.h"

#include <vector>

namespace mjb {
namespace {

std::string shaderLog(const GladGLContext& gl, GLuint sh) {
  GLint n = 0;
  gl.GetShaderiv(sh, GL_INFO_LOG_LENGTH, &n);
  std::vector<char> log(n > 0 ? n : 1, 0);
  gl.GetShaderInfoLog(sh, GLsizei(log.size()), nullptr, log.data());
  return log.data();
}

std::string programLog(const GladGLContext& gl, GLuint pr) {
  GLint n = 0;
  gl.GetProgramiv(pr, GL_INFO_LOG_LENGTH, &n);
  std::vector<char> log(n > 0 ? n : 1, 0);
  gl.GetProgramInfoLog(pr, GLsizei(log.size()), nullptr, log.data());
  return log.data();
}

GLuint build(const GladGLContext& gl, const std::string& label, const char* files,
             const char* src, std::string* err) {
  std::string where = label;
  if (files) where += " (source numbers in the log: " + std::string(files) + ")";

  GLuint sh = gl.CreateShader(GL_COMPUTE_SHADER);
  gl.ShaderSource(sh, 1, &src, nullptr);
  gl.CompileShader(sh);
  GLint ok = 0;
  gl.GetShaderiv(sh, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    *err = where + ": compile failed:\n" + shaderLog(gl, sh);
    gl.DeleteShader(sh);
    return 0;
  }

  GLuint pr = gl.CreateProgram();
  gl.AttachShader(pr, sh);
  gl.LinkProgram(pr);
  gl.DetachShader(pr, sh);
  gl.DeleteShader(sh);
  gl.GetProgramiv(pr, GL_LINK_STATUS, &ok);
  if (!ok) {
    *err = where + ": link failed:\n" + programLog(gl, pr);
    gl.DeleteProgram(pr);
    return 0;
  }
  // names the program in GL debuggers and debug output
  if (gl.ObjectLabel) gl.ObjectLabel(GL_PROGRAM, pr, -1, label.c_str());
  return pr;
}

}  // namespace

GLuint glProgram(const GladGLContext& gl, const char* name, std::string* err,
                 const std::string& defines) {
  const char* files = nullptr;
  const char* src = shaderSource(name, &files);
  if (!src) {
    *err = "shaders/" + std::string(name) + ": no such embedded shader";
    return 0;
  }
  if (defines.empty()) return build(gl, "shaders/" + std::string(name), files, src, err);
  // after the #version line, then #line 2 keeps the log's line numbers
  std::string s = src;
  size_t eol = s.find('\n');
  eol = eol == std::string::npos ? s.size() : eol + 1;
  s.insert(eol, defines + "#line 2 0\n");
  return build(gl, "shaders/" + std::string(name), files, s.c_str(), err);
}

GLuint glProgramSource(const GladGLContext& gl, const char* label, const char* src,
                       std::string* err) {
  return build(gl, label, nullptr, src, err);
}

}  // namespace mjb
