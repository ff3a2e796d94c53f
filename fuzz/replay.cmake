# Replays of the fuzz corpora as ordinary tests (any compiler, no libFuzzer): every fuzz/fuzz_*.c
# is built around fuzz/replay_main.c as fuzz_replay_<name> and replays fuzz/corpus/fuzz_<name>/
# with every check strict (FUZZ_STRICT=1): a regression input added to the corpus is a test, with
# no copy of the case in tests/. fuzz_scene and fuzz_world_scene (which need the tool's cJSON
# loaders) replay in the libFuzzer build only. Included from tests/CMakeLists.txt.
if(WIN32)
  return()
endif()
file(GLOB COLLIDE_REPLAY_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/fuzz/fuzz_*.c)
foreach(source IN LISTS COLLIDE_REPLAY_SOURCES)
  get_filename_component(name ${source} NAME_WE)
  if(name STREQUAL "fuzz_scene" OR name STREQUAL "fuzz_world_scene")
    continue()
  endif()
  string(REPLACE "fuzz_" "fuzz_replay_" replay ${name})
  add_executable(${replay} ${source} ${PROJECT_SOURCE_DIR}/fuzz/replay_main.c)
  target_link_libraries(${replay} PRIVATE collide::collide)
  target_include_directories(${replay} PRIVATE ${PROJECT_SOURCE_DIR}/src ${PROJECT_SOURCE_DIR}/tests
    ${PROJECT_SOURCE_DIR}/fuzz)
  target_compile_definitions(${replay} PRIVATE CD_ENABLE_ASSERT)
  if(COLLIDE_LIBM)
    target_link_libraries(${replay} PRIVATE m)
  endif()
  add_test(NAME ${replay} COMMAND ${replay} ${PROJECT_SOURCE_DIR}/fuzz/corpus/${name})
  set_tests_properties(${replay} PROPERTIES ENVIRONMENT "FUZZ_STRICT=1" LABELS fuzz-replay)
endforeach()
