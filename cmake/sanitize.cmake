# MJBUOY_SANITIZE: AddressSanitizer + UndefinedBehaviorSanitizer on every
# target of the project (library, tools, tests). Any UB report aborts the
# process (-fno-sanitize-recover), so a test that triggers one fails.
# The run-time options and the leak suppressions (tests/sanitizers) are
# compiled into every executable (their __asan_default_options & co.), so
# ctest, the python-driven tool tests and a manual run all get them; the
# usual ASAN_OPTIONS / UBSAN_OPTIONS / LSAN_OPTIONS still override them.
# MJBUOY_FUZZ: libFuzzer needs clang's -fsanitize=fuzzer runtime
# (Debian: clang, libclang-rt-14-dev); the fuzz targets add it themselves.
set(MJBUOY_SANITIZE_FLAGS -fsanitize=address,undefined -fno-sanitize-recover=all
  -fno-omit-frame-pointer)
if(MJBUOY_SANITIZE OR MJBUOY_FUZZ)
  # -O1 -g: readable stacks at a bearable speed (ASan's recommendation)
  add_compile_options(${MJBUOY_SANITIZE_FLAGS} -O1 -g)
  add_link_options(${MJBUOY_SANITIZE_FLAGS})
  add_library(mjbuoy_sanitizer_options OBJECT ${PROJECT_SOURCE_DIR}/tests/sanitizers/options.c)
  target_compile_definitions(mjbuoy_sanitizer_options PRIVATE
    MJB_LSAN_SUPP="${PROJECT_SOURCE_DIR}/tests/sanitizers/lsan.supp")
  # every target created after this line links the options object
  link_libraries(mjbuoy_sanitizer_options)
endif()
if(MJBUOY_FUZZ AND NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "MJBUOY_FUZZ needs clang for libFuzzer (-fsanitize=fuzzer), "
    "but CMAKE_CXX_COMPILER is ${CMAKE_CXX_COMPILER_ID}: apt-get install clang libclang-rt-14-dev "
    "and configure a fresh build dir with -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++")
endif()
if(MJBUOY_FUZZ)
  # libFuzzer's coverage feedback on all our code (library, tools), not
  # just the fuzz targets; the driver is linked by tests/fuzz only
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
