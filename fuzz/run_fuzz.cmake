# Runs one libFuzzer target briefly, as a CTest test:
#   cmake -DFUZZER=path -DSEED_DIRS="dir|dir" -DWORK_DIR=dir -DMAX_TOTAL_TIME=15 -DMAX_RUNS=N
#         [-DSKIP=check,check] -P run_fuzz.cmake
# The seed files are copied into WORK_DIR/seeds (fresh each run) and handed to the fuzzer as a
# list in name order; it grows WORK_DIR/corpus. Crash inputs land in WORK_DIR/ too, so the source
# tree is never written. Any crash, sanitizer report, failed check (abort), timeout or leak makes
# the fuzzer exit non-zero and the test fail.
#
# Runs are made repeatable: libFuzzer's path depends on the order it reads its seeds in (a
# directory's order is the file system's: the same seeds under other names took another path), on
# re-reading its corpus folder every second (-reload) and on the addresses it sees in comparisons
# (address-space layout randomisation, switched off with setarch -R where the kernel allows it).
# With those fixed, repeated runs of one binary take the same path, so a CI failure replays and a
# clean run before landing says much more about CI's.
foreach(var IN ITEMS FUZZER WORK_DIR MAX_TOTAL_TIME MAX_RUNS)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_fuzz.cmake: ${var} is not set")
  endif()
endforeach()

set(corpus ${WORK_DIR}/corpus)
set(seed_copy ${WORK_DIR}/seeds)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${corpus} ${seed_copy})
string(REPLACE "|" ";" seed_dirs "${SEED_DIRS}")
set(seed_count 0)
set(seed_list "")
foreach(dir IN LISTS seed_dirs)
  if(IS_DIRECTORY ${dir})
    # file(GLOB) sorts its result: the list's order is the names' order.
    file(GLOB seeds LIST_DIRECTORIES false ${dir}/*)
    foreach(seed IN LISTS seeds)
      # Prefixed with the folder name: examples/ and examples/bad/ may hold files of one name.
      get_filename_component(parent ${dir} NAME)
      get_filename_component(file_name ${seed} NAME)
      set(copy ${seed_copy}/${parent}-${file_name})
      configure_file(${seed} ${copy} COPYONLY)
      if(seed_count GREATER 0)
        string(APPEND seed_list ",")
      endif()
      string(APPEND seed_list "${copy}")
      math(EXPR seed_count "${seed_count} + 1")
    endforeach()
  endif()
endforeach()
set(seed_option "")
if(seed_count GREATER 0)
  # No newline at the end: libFuzzer would read it as part of the last name.
  file(WRITE ${WORK_DIR}/seed_list "${seed_list}")
  set(seed_option -seed_inputs=@${WORK_DIR}/seed_list)
endif()
# setarch -R runs the fuzzer without address-space randomisation; a kernel or container that
# refuses it leaves the run as it was (still correct, only not replayable bit for bit).
set(launcher "")
find_program(SETARCH setarch)
if(SETARCH)
  execute_process(COMMAND ${SETARCH} -R true RESULT_VARIABLE setarch_status OUTPUT_QUIET ERROR_QUIET)
  if(setarch_status EQUAL 0)
    set(launcher ${SETARCH} -R)
  endif()
endif()
if(NOT launcher)
  message(STATUS "setarch -R is not available here: this run's path may differ from another machine's")
endif()
message(STATUS "${FUZZER}: ${seed_count} seed inputs, at most ${MAX_TOTAL_TIME} s or ${MAX_RUNS} runs")
# Checks to pass over (fuzz_common.h, FuzzSkipped); said aloud so that a skip is never silent.
set(ENV{FUZZ_SKIP} "${SKIP}")
if(SKIP)
  message(STATUS "skipping the checks: ${SKIP}")
endif()

execute_process(
  COMMAND ${launcher} ${FUZZER} -max_total_time=${MAX_TOTAL_TIME} -runs=${MAX_RUNS} -timeout=20 -seed=1
    -reload=0 ${seed_option} -print_final_stats=1 -artifact_prefix=${WORK_DIR}/ ${corpus}
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
