# Runs one libFuzzer target briefly, as a CTest test:
#   cmake -DFUZZER=path -DSEED_DIRS="dir|dir" -DWORK_DIR=dir -DMAX_TOTAL_TIME=15 -DMAX_RUNS=N
#         [-DSKIP=check,check] -P run_fuzz.cmake
# The seed files are copied into WORK_DIR/corpus (fresh each run), which the fuzzer then grows;
# crash inputs land in WORK_DIR/ too, so the source tree is never written. Any crash, sanitizer
# report, failed check (abort), timeout or leak makes the fuzzer exit non-zero and the test fail.
foreach(var IN ITEMS FUZZER WORK_DIR MAX_TOTAL_TIME MAX_RUNS)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_fuzz.cmake: ${var} is not set")
  endif()
endforeach()

set(corpus ${WORK_DIR}/corpus)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${corpus})
string(REPLACE "|" ";" seed_dirs "${SEED_DIRS}")
set(seed_count 0)
foreach(dir IN LISTS seed_dirs)
  if(IS_DIRECTORY ${dir})
    file(GLOB seeds LIST_DIRECTORIES false ${dir}/*)
    foreach(seed IN LISTS seeds)
      # Prefixed with the folder name: examples/ and examples/bad/ may hold files of one name.
      get_filename_component(parent ${dir} NAME)
      get_filename_component(file_name ${seed} NAME)
      configure_file(${seed} ${corpus}/${parent}-${file_name} COPYONLY)
      math(EXPR seed_count "${seed_count} + 1")
    endforeach()
  endif()
endforeach()
message(STATUS "${FUZZER}: ${seed_count} seed inputs, at most ${MAX_TOTAL_TIME} s or ${MAX_RUNS} runs")
# Checks to pass over (fuzz_common.h, FuzzSkipped); said aloud so that a skip is never silent.
set(ENV{FUZZ_SKIP} "${SKIP}")
if(SKIP)
  message(STATUS "skipping the checks: ${SKIP}")
endif()

execute_process(
  COMMAND ${FUZZER} -max_total_time=${MAX_TOTAL_TIME} -runs=${MAX_RUNS} -timeout=20 -seed=1
    -print_final_stats=1 -artifact_prefix=${WORK_DIR}/ ${corpus}
  WORKING_DIRECTORY ${WORK_DIR}
  RESULT_VARIABLE status
  OUTPUT_VARIABLE output
  ERROR_VARIABLE output)

# libFuzzer prints the progress and the final statistics on stderr; keep the end of it.
string(LENGTH "${output}" length)
if(length GREATER 6000)
  math(EXPR start "${length} - 6000")
  string(SUBSTRING "${output}" ${start} -1 output)
  set(output "...\n${output}")
endif()
message("${output}")
if(NOT status EQUAL 0)
  file(GLOB artifacts ${WORK_DIR}/crash-* ${WORK_DIR}/timeout-* ${WORK_DIR}/leak-* ${WORK_DIR}/oom-*)
  message(FATAL_ERROR "${FUZZER} failed (exit status ${status}); reproducer(s): ${artifacts}")
endif()
