# ctest fuzz.<harness>: runs one libFuzzer harness for SECONDS seconds on its seed corpus
# (fuzz/corpus/<harness>), growing a working corpus in WORK_DIR; a finding (a crash, a
# sanitizer report, a failed check, a hang of more than 10 s on one input, more than 2 GB)
# fails the test, and libFuzzer's reproducer file is left in WORK_DIR. Says "SKIPPED:"
# (the test's SKIP_REGULAR_EXPRESSION) when fuzz.build was skipped.
#   cmake -DHARNESS=<path> -DSEEDS=<dir> -DWORK_DIR=<dir> -DSECONDS=<n> [-DOPTIONS=<libFuzzer options>] -P run.cmake
if(NOT EXISTS ${HARNESS})
  message("SKIPPED: ${HARNESS} was not built (see the output of fuzz.build)")
  return()
endif()
file(MAKE_DIRECTORY ${WORK_DIR}/corpus)
separate_arguments(OPTIONS)
execute_process(COMMAND ${HARNESS} -max_total_time=${SECONDS} -timeout=10 -rss_limit_mb=2048 ${OPTIONS}
                        -print_final_stats=1 -artifact_prefix=${WORK_DIR}/ ${WORK_DIR}/corpus ${SEEDS}
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "libFuzzer found a problem (exit status ${status}); reproducer in ${WORK_DIR}:\n${err}")
endif()
string(REGEX MATCH "stat::number_of_executed_units: *[0-9]+" runs "${err}")
string(REGEX MATCH "cov: [0-9]+" coverage "${err}")
message("${HARNESS}: ${runs}, ${coverage} edges, no finding in ${SECONDS} s")
