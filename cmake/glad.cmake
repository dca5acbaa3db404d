# Generates mjbuoy's GL loader with Debian's python3-glad (glad 2), at build
# time, into OUT (build tree). Run with cmake -P; inputs: PYTHON, OUT.
#
# options: gl:core=4.5 with only GL_KHR_debug (the core API is all we call;
# no extension list keeps the files 4x smaller), --mx so the function
# pointers live in a GladGLContext struct of ours instead of globals that a
# user's own glad would clash with, --reproducible so glad uses its packaged
# Khronos specs instead of fetching them. The two global loader functions
# are renamed gladLoadGL* -> mjbLoadGL* so a program that links glad 2
# itself still links.
cmake_minimum_required(VERSION 3.16)
if(NOT PYTHON OR NOT OUT)
  message(FATAL_ERROR "glad.cmake: set PYTHON and OUT")
endif()

file(REMOVE_RECURSE ${OUT})
execute_process(
  COMMAND ${PYTHON} -m glad --quiet --reproducible
    --api gl:core=4.5 --extensions GL_KHR_debug --out-path ${OUT} c --mx
  RESULT_VARIABLE rc
  ERROR_VARIABLE log)
if(NOT rc EQUAL 0 OR NOT EXISTS ${OUT}/src/gl.c)
  message(FATAL_ERROR "glad.cmake: '${PYTHON} -m glad' failed (${rc}):\n${log}")
endif()

foreach(f ${OUT}/src/gl.c ${OUT}/include/glad/gl.h)
  file(READ ${f} text)
  string(REPLACE "gladLoadGLContext" "mjbLoadGLContext" text "${text}")
  file(WRITE ${f} "${text}")
endforeach()
