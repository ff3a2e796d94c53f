# Driver of the package_consumer test: cmake -DBUILD_DIR=... -P package_test.cmake
# (tests/package/CMakeLists.txt passes every variable; nothing depends on the current directory).
#   BUILD_DIR      the configured and built collide build tree
#   CONFIG         its configuration (build type)
#   WORK_DIR       scratch directory, wiped first; the install prefix is WORK_DIR/prefix
#   CONSUMER_DIR   tests/package/consumer
#   GENERATOR      CMake generator for the consumer
#   C_COMPILER     the compiler the library was built with
#   COMPILE_FLAGS  LINK_FLAGS  extra flags the library was built with (sanitizers)
#   EXPECT_DOUBLE  1 when the build has cdReal = double
#   VERSION        the project version the package must report
cmake_minimum_required(VERSION 3.20)

foreach(variable IN ITEMS BUILD_DIR WORK_DIR CONSUMER_DIR GENERATOR C_COMPILER EXPECT_DOUBLE VERSION)
  if(NOT DEFINED ${variable} OR "${${variable}}" STREQUAL "")
    message(FATAL_ERROR "package_test.cmake: ${variable} is not set")
  endif()
endforeach()

# Runs a command; on failure prints it with its output and stops the test.
function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(NOT result EQUAL 0)
    string(JOIN " " command ${ARGN})
    message(FATAL_ERROR "${what} failed (${result}):\n  ${command}\n${output}")
  endif()
  message(STATUS "${what}: ok")
  string(STRIP "${output}" output)
  set(step_output "${output}" PARENT_SCOPE)
endfunction()

set(prefix ${WORK_DIR}/prefix)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

# ---- (a) install the built tree ---------------------------------------------------------------
set(config_args)
if(CONFIG)
  set(config_args --config ${CONFIG})
endif()
run_step("install into ${prefix}" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix} ${config_args})

file(GLOB_RECURSE pc_files ${prefix}/collide.pc)
file(GLOB_RECURSE config_files ${prefix}/collideConfig.cmake)
if(NOT pc_files OR NOT config_files)
  message(FATAL_ERROR "the install has no collide.pc or collideConfig.cmake: '${pc_files}' '${config_files}'")
endif()
list(GET pc_files 0 pc_file)
get_filename_component(pkgconfig_dir ${pc_file} DIRECTORY)
get_filename_component(libdir ${pkgconfig_dir} DIRECTORY)

# ---- (b) a CMake project using find_package(collide CONFIG REQUIRED) ---------------------------
set(cmake_build ${WORK_DIR}/cmake-consumer)
run_step("configure the find_package consumer" ${CMAKE_COMMAND} -S ${CONSUMER_DIR} -B ${cmake_build}
  -G ${GENERATOR}
  -DCMAKE_C_COMPILER=${C_COMPILER}
  -DCMAKE_BUILD_TYPE=${CONFIG}
  -DCMAKE_PREFIX_PATH=${prefix}
  -DEXPECTED_VERSION=${VERSION}
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
  "-DCMAKE_C_FLAGS=${COMPILE_FLAGS}"
  "-DCMAKE_EXE_LINKER_FLAGS=${LINK_FLAGS}")
# The package must come from the fresh prefix, not from a collide installed on the machine.
file(STRINGS ${cmake_build}/CMakeCache.txt found_dir REGEX "^collide_DIR:")
string(FIND "${found_dir}" "${prefix}/" at)
if(NOT at GREATER -1)
  message(FATAL_ERROR "find_package(collide) found '${found_dir}' instead of the package in ${prefix}")
endif()
run_step("build the find_package consumer" ${CMAKE_COMMAND} --build ${cmake_build} ${config_args})
foreach(program IN ITEMS consumer_collide consumer_collide_shared)
  file(GLOB_RECURSE executable ${cmake_build}/${program} ${cmake_build}/${program}.exe)
  if(NOT executable)
    message(FATAL_ERROR "the consumer build produced no ${program}")
  endif()
  list(GET executable 0 executable)
  run_step("run ${program}" ${executable})
  message(STATUS "  ${step_output}")
endforeach()

# ---- (c) a plain compiler call with the flags from pkg-config ----------------------------------
find_program(PKG_CONFIG_EXECUTABLE NAMES pkg-config pkgconf)
if(NOT PKG_CONFIG_EXECUTABLE)
  message(FATAL_ERROR "pkg-config is not installed; the collide.pc check cannot run")
endif()
set(ENV{PKG_CONFIG_PATH} ${pkgconfig_dir})
run_step("pkg-config --cflags --libs collide" ${PKG_CONFIG_EXECUTABLE} --cflags --libs collide)
string(STRIP "${step_output}" pkg_flags)
# The flags must point into the fresh prefix: collide.pc has to follow `--prefix`.
string(FIND "${pkg_flags}" "${prefix}" at)
if(NOT at GREATER -1)
  message(FATAL_ERROR "pkg-config gave '${pkg_flags}', which does not point into ${prefix}")
endif()
separate_arguments(pkg_flags UNIX_COMMAND "${pkg_flags}")
separate_arguments(extra_compile UNIX_COMMAND "${COMPILE_FLAGS}")
separate_arguments(extra_link UNIX_COMMAND "${LINK_FLAGS}")
set(pc_program ${WORK_DIR}/consumer_pkg_config)
run_step("compile with pkg-config flags" ${C_COMPILER} ${extra_compile} -Wall -Wextra -Wpedantic -Werror
  -DCONSUMER_EXPECT_DOUBLE=${EXPECT_DOUBLE} ${CONSUMER_DIR}/main.c -o ${pc_program} ${pkg_flags} ${extra_link})
# -lcollide picks the shared library when both are installed; the loader finds it in libdir.
set(ENV{LD_LIBRARY_PATH} "${libdir}:$ENV{LD_LIBRARY_PATH}")
run_step("run consumer_pkg_config" ${pc_program})
message(STATUS "  ${step_output}")
