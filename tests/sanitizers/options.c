/* sanitizer run-time defaults of every executable of a MJBUOY_SANITIZE or
   MJBUOY_FUZZ build (cmake/sanitize.cmake); the sanitizers call these once
   at start-up, and the environment variables ASAN_OPTIONS, UBSAN_OPTIONS
   and LSAN_OPTIONS override them */

/* stop at the first error (a test with one fails); check for leaks at exit */
const char* __asan_default_options(void) {
  return "halt_on_error=1:detect_leaks=1:check_initialization_order=1:"
         "strict_init_order=1:detect_stack_use_after_return=1";
}

/* -fno-sanitize-recover already aborts; stacks make the report usable */
const char* __ubsan_default_options(void) {
  return "halt_on_error=1:print_stacktrace=1";
}

/* leaks in third-party code only (Mesa's llvmpipe, LLVM, EGL, MuJoCo's
   global state): tests/sanitizers/lsan.supp, each entry says why */
const char* __lsan_default_options(void) {
  return "suppressions=" MJB_LSAN_SUPP ":print_suppressions=0";
}
