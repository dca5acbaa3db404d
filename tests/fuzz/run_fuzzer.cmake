# one bounded libFuzzer run (tests/fuzz/CMakeLists.txt): copy the seed
# corpus to WORK/corpus, fuzz for SECONDS (with the dictionary DICT if it
# exists), fail on any finding.
# -timeout=10: an input that takes over 10 s is a finding (a hang);
# -rss_limit_mb: the sanitizers' shadow memory plus MuJoCo's arena.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/corpus)
file(GLOB seeds ${CORPUS}/*)
file(COPY ${seeds} DESTINATION ${WORK}/corpus)
set(dict)
if(EXISTS "${DICT}")
  set(dict -dict=${DICT})
endif()
execute_process(
  COMMAND ${FUZZER} ${dict} -max_total_time=${SECONDS} -timeout=10 -rss_limit_mb=4096
    -print_final_stats=1 -artifact_prefix=${WORK}/ ${WORK}/corpus
  WORKING_DIRECTORY ${WORK}
  RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  file(GLOB found ${WORK}/crash-* ${WORK}/timeout-* ${WORK}/oom-* ${WORK}/leak-*)
  message(FATAL_ERROR "${FUZZER} failed (exit ${rc}); inputs: ${found}")
endif()
