# Run by the package.consumer and package.planner tests (see CMakeLists.txt here) as
#   cmake -DMINK_SOURCE_DIR=... -DCONSUMER_SOURCE_DIR=... -DWORK_DIR=... -DGENERATOR=...
#         [-DCXX_COMPILER=...] [-DEIGEN3_DIR=...] [-DCGAL_DIR=...]
#         [-DCONSUMER_EXECUTABLE=name[,name...]] -P package_test.cmake
# Steps: configure mink alone (tests, benchmarks, examples off) and install it into
# WORK_DIR/prefix; check the installed files (no installed header uses CGAL); build the
# consumer project against the prefix only (CGAL_DIR, when given, is passed on to it);
# run its executables CONSUMER_EXECUTABLE (comma-separated; default: consumer) in its
# build directory. Any failure stops the script with a message (non-zero exit).
cmake_minimum_required(VERSION 3.20)

foreach(var MINK_SOURCE_DIR CONSUMER_SOURCE_DIR WORK_DIR GENERATOR)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "package test: -D${var}=... is required")
  endif()
endforeach()

set(mink_build "${WORK_DIR}/mink-build")
set(prefix "${WORK_DIR}/prefix")
set(consumer_build "${WORK_DIR}/consumer-build")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

set(common_args -G "${GENERATOR}" -DCMAKE_BUILD_TYPE=Release)
if(CXX_COMPILER)
  list(APPEND common_args "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}")
endif()
if(EIGEN3_DIR)
  list(APPEND common_args "-DEigen3_DIR=${EIGEN3_DIR}")
endif()

function(step name)
  execute_process(COMMAND ${ARGN}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "package test: ${name} failed (${rc}):\n${out}")
  endif()
  message(STATUS "package test: ${name}: ok")
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

# 1. Install mink from a fresh configure of the source tree.
step("configure mink" ${CMAKE_COMMAND} -S "${MINK_SOURCE_DIR}" -B "${mink_build}" ${common_args}
     -DMINK_BUILD_TESTS=OFF -DMINK_BUILD_BENCHMARKS=OFF -DMINK_BUILD_EXAMPLES=OFF
     "-DCMAKE_INSTALL_PREFIX=${prefix}")
step("build mink" ${CMAKE_COMMAND} --build "${mink_build}")
step("install mink" ${CMAKE_COMMAND} --install "${mink_build}" --prefix "${prefix}")

# 2. The installed tree: headers under include/mink, CMake files under share/cmake/mink,
#    the optional instantiation source share/mink/mink_instantiations.cpp, nothing else,
#    and no trace of a test, benchmark or example dependency.
file(GLOB_RECURSE installed RELATIVE "${prefix}" "${prefix}/*")
foreach(f IN LISTS installed)
  if(NOT f MATCHES "^include/mink/.*\\.(hpp|hxx|h|inl)$" AND NOT f MATCHES "^share/cmake/mink/[^/]+\\.cmake$"
     AND NOT f STREQUAL "share/mink/mink_instantiations.cpp")
    message(FATAL_ERROR "package test: unexpected installed file ${prefix}/${f}")
  endif()
endforeach()
foreach(required include/mink/mink.hpp share/cmake/mink/minkConfig.cmake
                 share/cmake/mink/minkConfigVersion.cmake share/cmake/mink/minkTargets.cmake)
  if(NOT EXISTS "${prefix}/${required}")
    message(FATAL_ERROR "package test: ${prefix}/${required} was not installed")
  endif()
endforeach()
set(test_only_in_cmake "CGAL|GTest|GTEST|gtest|gmock|fcl|FCL|ccd|CCD|benchmark::|Bullet|BULLET|GMP|MPFR")
set(test_only_in_headers
    "#[ \t]*include[ \t]*[<\"](CGAL|gtest|gmock|fcl|ccd|benchmark|btBullet|LinearMath|BulletCollision|gmp|mpfr)")
foreach(f IN LISTS installed)
  file(READ "${prefix}/${f}" content)
  if(f MATCHES "\\.cmake$")
    set(pattern "${test_only_in_cmake}")
  else()
    set(pattern "${test_only_in_headers}")
  endif()
  string(REGEX MATCH "${pattern}" hit "${content}")
  if(hit)
    message(FATAL_ERROR "package test: installed file ${prefix}/${f} mentions '${hit}', "
                        "a dependency of mink's tests/benchmarks only")
  endif()
endforeach()
list(LENGTH installed installed_count)
message(STATUS "package test: ${installed_count} installed files checked: ok")

# CGAL in particular, beyond its includes (the consumer below calls mddExact<CGAL::Gmpq>,
# so CGAL must come from the consumer alone): no installed header's code names it in any
# spelling. Comments may, where they give CGAL::Gmpq as an example of the exact type a
# caller supplies; they are stripped first and only counted.
set(cgal_in_comments "")
foreach(f IN LISTS installed)
  if(NOT f MATCHES "^include/")
    continue()
  endif()
  file(READ "${prefix}/${f}" content)
  string(REGEX REPLACE "/\\*([^*]|\\*+[^*/])*\\*+/" "" code "${content}")
  string(REGEX REPLACE "//[^\n]*" "" code "${code}")
  string(REGEX MATCH "[Cc][Gg][Aa][Ll][^\n]*" hit "${code}")
  if(hit)
    message(FATAL_ERROR "package test: installed header ${prefix}/${f} uses CGAL outside comments: '${hit}'")
  endif()
  if(content MATCHES "[Cc][Gg][Aa][Ll]")
    list(APPEND cgal_in_comments "${f}")
  endif()
endforeach()
list(LENGTH cgal_in_comments cgal_comment_count)
message(STATUS "package test: no installed header uses CGAL (${cgal_comment_count} name it in comments: "
               "${cgal_in_comments}): ok")

# 3. Build the consumer against the prefix alone (no package registry, no source tree).
set(consumer_args "")
if(CGAL_DIR)
  list(APPEND consumer_args "-DCGAL_DIR=${CGAL_DIR}")
endif()
step("configure consumer" ${CMAKE_COMMAND} -S "${CONSUMER_SOURCE_DIR}" -B "${consumer_build}"
     ${common_args} ${consumer_args} "-DCMAKE_PREFIX_PATH=${prefix}" "-DMINK_EXPECTED_PREFIX=${prefix}"
     -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF -DCMAKE_FIND_USE_SYSTEM_PACKAGE_REGISTRY=OFF)
step("build consumer" ${CMAKE_COMMAND} --build "${consumer_build}")

# 4. Run each of its programs (in its build directory, where they may write files): each
#    checks its own results and exits non-zero on a mismatch. A program named here that
#    the consumer did not build is a failure.
if(NOT CONSUMER_EXECUTABLE)
  set(CONSUMER_EXECUTABLE consumer)
endif()
string(REPLACE "," ";" programs "${CONSUMER_EXECUTABLE}")
foreach(program IN LISTS programs)
  if(NOT EXISTS "${consumer_build}/${program}")
    message(FATAL_ERROR "package test: the consumer did not build ${program}")
  endif()
  execute_process(COMMAND "${consumer_build}/${program}" WORKING_DIRECTORY "${consumer_build}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE step_output ERROR_VARIABLE step_output)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "package test: run ${program} failed (${rc}):\n${step_output}")
  endif()
  message(STATUS "package test: run ${program}: ok")
  message(STATUS "${program} output:\n${step_output}")
endforeach()
