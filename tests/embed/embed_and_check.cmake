# ctest's embedding test: configure tests/embed (which does add_subdirectory on this source tree),
# check through CMake's file API that it defines no targets but the library and its own program
# (no CLI, viewer, tests, benchmarks or tools) and that no build type was forced on it, then build
# and run it. Variables: SOURCE_DIR (holefill's tree), WORK_DIR, GENERATOR, COMPILER, LAUNCHER
# (the compiler launcher, may be empty) and VERSION.
file(REMOVE_RECURSE ${WORK_DIR})
include(${CMAKE_CURRENT_LIST_DIR}/../package/run_or_fail.cmake)

set(build ${WORK_DIR}/build)
file(WRITE ${build}/.cmake/api/v1/query/codemodel-v2 "")
# Unity batches: the library is compiled once more here, in a third of the CPU time it takes file
# by file (30 s against 96 s, GCC 12 at -O0).
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/embed -B ${build} -G ${GENERATOR}
    -DHOLEFILL_SOURCE_DIR=${SOURCE_DIR} -DCMAKE_CXX_COMPILER=${COMPILER}
    "-DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER}" -DCMAKE_UNITY_BUILD=ON
    -DCMAKE_UNITY_BUILD_BATCH_SIZE=16)

file(STRINGS ${build}/CMakeCache.txt build_type REGEX "^CMAKE_BUILD_TYPE:")
if(NOT build_type MATCHES "^CMAKE_BUILD_TYPE:[A-Z]*=$")
  message(FATAL_ERROR "holefill set the embedding project's build type: ${build_type}")
endif()

# Every target the configuration defines, from the file API's code model.
file(GLOB index ${build}/.cmake/api/v1/reply/index-*.json)
file(READ ${index} text)
string(JSON codemodel GET "${text}" reply codemodel-v2 jsonFile)
file(READ ${build}/.cmake/api/v1/reply/${codemodel} text)
string(JSON count LENGTH "${text}" configurations 0 targets)
set(built "")
math(EXPR last "${count} - 1")
foreach(i RANGE ${last})
  string(JSON target_file GET "${text}" configurations 0 targets ${i} jsonFile)
  file(READ ${build}/.cmake/api/v1/reply/${target_file} target)
  string(JSON type GET "${target}" type)
  string(JSON name GET "${target}" name)
  # Interface libraries (holefill's warning flags) have nothing to build.
  if(NOT type STREQUAL "INTERFACE_LIBRARY")
    list(APPEND built ${name})
  endif()
endforeach()
list(SORT built)
if(NOT built STREQUAL "embedder;holefill_core")
  message(FATAL_ERROR "the embedding project builds ${built}; expected embedder;holefill_core")
endif()

run(${CMAKE_COMMAND} --build ${build})
run(${build}/embedder ${VERSION})
file(REMOVE_RECURSE ${WORK_DIR})
