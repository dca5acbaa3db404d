# Embeds the compute shaders shaders/*.comp into the library as string
# constants, at build time: writes OUT, a .cc with mjb::shaderSource(name)
# and mjb::shaderName(i) (declared in mjbuoy/gl/glprog.h). Run with cmake -P;
# inputs: SRC (the shaders/ directory), OUT.
#
# A line '#include "file"' in a shader is replaced by shaders/file (one
# level, no nesting), framed by #line directives so the driver's log keeps
# the shader's own line numbers: source string 0 is the shader, 1, 2, ...
# the included files in order. The shaders then need no file at run time.
cmake_minimum_required(VERSION 3.16)
if(NOT SRC OR NOT OUT)
  message(FATAL_ERROR "embed_shaders.cmake: set SRC and OUT")
endif()

file(GLOB comps ${SRC}/*.comp)
list(SORT comps)
set(entries "")
foreach(path ${comps})
  get_filename_component(name ${path} NAME)
  file(READ ${path} rest)
  set(out "")
  set(files "0 shaders/${name}")
  set(nsrc 0)
  set(base 1)  # line number, in the shader, of the first line of rest
  while(TRUE)
    string(REGEX MATCH "\n#include \"([A-Za-z0-9_./-]+)\"[^\n]*" inc "${rest}")
    if(NOT inc)
      break()
    endif()
    set(file ${CMAKE_MATCH_1})
    if(NOT EXISTS ${SRC}/${file})
      message(FATAL_ERROR "shaders/${name}: #include \"${file}\": no such file in shaders/")
    endif()
    math(EXPR nsrc "${nsrc} + 1")
    string(APPEND files ", ${nsrc} shaders/${file}")
    file(READ ${SRC}/${file} body)
    string(REGEX REPLACE "\n+$" "" body "${body}")

    string(FIND "${rest}" "${inc}" pos)
    string(SUBSTRING "${rest}" 0 ${pos} head)
    string(LENGTH "${inc}" len)
    math(EXPR pos "${pos} + ${len}")
    string(SUBSTRING "${rest}" ${pos} -1 rest)
    string(REGEX MATCHALL "\n" nl "${head}")
    list(LENGTH nl k)
    math(EXPR base "${base} + ${k} + 1")  # the include's line
    math(EXPR next "${base} + 1")
    string(APPEND out "${head}\n#line 1 ${nsrc}\n${body}\n#line ${next} 0")
  endwhile()
  string(APPEND out "${rest}")

  string(FIND "${out}" ")glsl\"" bad)
  if(NOT bad EQUAL -1)
    message(FATAL_ERROR "shaders/${name}: contains ')glsl\"', which ends the raw string")
  endif()
  string(APPEND entries "  {\"${name}\", \"${files}\", R\"glsl(${out})glsl\"},\n")
endforeach()

file(WRITE ${OUT} "\
// generated from shaders/ by cmake/embed_shaders.cmake at build time: do not edit
#include <cstring>

#include \"gl/glprog.h\"

namespace mjb {
namespace {

struct Embedded {
  const char* name;   // file name in shaders/
  const char* files;  // what the source string numbers of the driver's log are
  const char* src;    // GLSL, includes pasted in
};

const Embedded kShader[] = {
${entries}  {nullptr, nullptr, nullptr},
};

}  // namespace

const char* shaderSource(const char* name, const char** files) {
  for (const Embedded* e = kShader; e->name; e++) {
    if (!std::strcmp(e->name, name)) {
      if (files) *files = e->files;
      return e->src;
    }
  }
  return nullptr;
}

const char* shaderName(int i) {
  int n = sizeof(kShader) / sizeof(kShader[0]) - 1;
  return i >= 0 && i < n ? kShader[i].name : nullptr;
}

}  // namespace mjb
")
