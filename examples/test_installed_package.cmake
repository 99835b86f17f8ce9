# CTest example-installed-package, run as
#   cmake -DBUILD_DIR=... -DCONFIG=... -DSOURCE_DIR=... -DWORK_DIR=... -DGENERATOR=...
#         [-DMAKE_PROGRAM=...] [-DCXX_COMPILER=...] [-DFLAGS=...] -P test_installed_package.cmake
# 1. installs the built project from BUILD_DIR into WORK_DIR/prefix;
# 2. configures and builds SOURCE_DIR (examples/heartbeat) standalone against that prefix,
#    checking that find_package(tioa) found the package there and nowhere else;
# 3. checks the program it builds with check_heartbeat.cmake (its commands, exit codes and
#    reports), as example-heartbeat does for the in-tree build.

foreach(var BUILD_DIR CONFIG SOURCE_DIR WORK_DIR GENERATOR)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "test_installed_package.cmake: -D${var}=... is required")
  endif()
endforeach()

set(prefix ${WORK_DIR}/prefix)
set(build ${WORK_DIR}/build)
file(REMOVE_RECURSE ${WORK_DIR})

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${out}")
  endif()
  message(STATUS "${what}: ok")
  set(output "${out}" PARENT_SCOPE)
endfunction()

run("install into ${prefix}" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix} --config ${CONFIG})

set(configure_args -S ${SOURCE_DIR} -B ${build} -G ${GENERATOR}
    -DCMAKE_BUILD_TYPE=${CONFIG}
    -DCMAKE_PREFIX_PATH=${prefix}
    -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
    -DCMAKE_FIND_USE_SYSTEM_PACKAGE_REGISTRY=OFF)
if(MAKE_PROGRAM)
  list(APPEND configure_args -DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM})
endif()
if(CXX_COMPILER)
  list(APPEND configure_args -DCMAKE_CXX_COMPILER=${CXX_COMPILER})
endif()
if(FLAGS)
  list(APPEND configure_args "-DCMAKE_CXX_FLAGS=${FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${FLAGS}")
endif()
run("configure examples/heartbeat standalone" ${CMAKE_COMMAND} ${configure_args})

# The package must come from the prefix, not from a system-wide install.
file(STRINGS ${build}/CMakeCache.txt tioa_dir REGEX "^tioa_DIR:")
string(REGEX REPLACE "^tioa_DIR:[A-Z]+=" "" tioa_dir "${tioa_dir}")
file(REAL_PATH "${tioa_dir}" tioa_dir)
file(REAL_PATH "${prefix}" real_prefix)
string(FIND "${tioa_dir}" "${real_prefix}/" at)
if(NOT at EQUAL 0)
  message(FATAL_ERROR "find_package(tioa) found '${tioa_dir}', not the package in ${prefix}")
endif()
message(STATUS "find_package(tioa) found ${tioa_dir}")

run("build examples/heartbeat" ${CMAKE_COMMAND} --build ${build} --config ${CONFIG})

foreach(candidate ${build}/heartbeat ${build}/${CONFIG}/heartbeat)
  if(EXISTS ${candidate})
    set(program ${candidate})
    break()
  endif()
endforeach()
if(NOT program)
  message(FATAL_ERROR "the standalone build produced no heartbeat executable in ${build}")
endif()
set(PROGRAM ${program})
set(WORK_DIR ${WORK_DIR}/out)
include(${CMAKE_CURRENT_LIST_DIR}/check_heartbeat.cmake)
