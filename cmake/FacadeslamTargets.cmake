include(TestSuiteDiscovery)

# Project-wide compile settings, applied per target so dependencies are not
# affected: strict warnings as errors, and the optional sanitizers.
add_library(facadeslam_options INTERFACE)
target_compile_options(facadeslam_options INTERFACE -Wall -Wextra -Wpedantic -Werror)
target_include_directories(facadeslam_options INTERFACE ${PROJECT_SOURCE_DIR})

if(CMAKE_UNITY_BUILD AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  # A unity build includes each .cpp into a batch file, so GCC takes a class
  # defined in a .cpp with a member of an anonymous-namespace type (a
  # pimpl's vertex struct, say) for a header-defined class and warns; in a
  # .cpp that is what we mean.
  target_compile_options(facadeslam_options INTERFACE -Wno-subobject-linkage)
endif()

if(FACADESLAM_SANITIZE STREQUAL "address")
  set(_fs_san -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  # Eigen stops trusting malloc's 16-byte alignment when it sees ASan
  # (__SANITIZE_ADDRESS__) and frees through its own aligned header, while the
  # uninstrumented libceres allocates with plain malloc: a Ceres-allocated
  # matrix freed in our code (e.g. ceres::GradientChecker's results) is then a
  # bad free. Both sides must agree; ASan's malloc does return 16-byte
  # aligned blocks on x86-64, which libceres already relies on.
  set(_fs_san_defs EIGEN_MALLOC_ALREADY_ALIGNED=1)
elseif(FACADESLAM_SANITIZE STREQUAL "thread")
  set(_fs_san -fsanitize=thread -fno-omit-frame-pointer)
elseif(NOT FACADESLAM_SANITIZE STREQUAL "")
  message(FATAL_ERROR "FACADESLAM_SANITIZE must be empty, 'address' (ASan + UBSan; with clang also the fuzz targets) or 'thread', not '${FACADESLAM_SANITIZE}'")
endif()
if(_fs_san)
  target_compile_definitions(facadeslam_options INTERFACE ${_fs_san_defs})
  # No -g here: the build type chooses the debug information (CI uses -g1).
  target_compile_options(facadeslam_options INTERFACE ${_fs_san})
  target_link_options(facadeslam_options INTERFACE ${_fs_san})
endif()

# facadeslam_library(NAME SOURCES ... DEPS ...): one static library per
# architectural folder, linked with the project options.
function(facadeslam_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_library(${name} STATIC ${ARG_SOURCES})
  target_link_libraries(${name} PUBLIC facadeslam_options ${ARG_DEPS})
endfunction()

# facadeslam_test(NAME SOURCES ... DEPS ... [LABEL unit|regression]): one gtest
# executable, its tests registered with CTest under the label (default
# `unit`; CI runs the `unit` label again under the sanitizers, while the
# `regression` tests, whole SLAM runs, only run in the optimised build).
# Tests run from the project root so that paths such as ../shared/data and
# configs/ resolve as they do for a user.
#
# Every test program sees the same third-party headers and macros
# (facadeslam_test_deps) so that they can all share one precompiled header:
# gtest, Eigen, OpenCV and Ceres take 2-3 s to parse per file, which was a
# third of CI's build time across the ~130 test files.
option(FACADESLAM_PCH "Share one precompiled header of the third-party headers across the tests" ON)
# The test programs' own code is compiled at -O1 in the optimised builds and
# at -O0 under the sanitizers: gtest bodies and the Ceres/Eigen templates
# instantiated in tests take the optimiser (twice as long when instrumented)
# most of their compile time, while the heavy work the tests exercise runs in
# the libraries, which keep the build type's optimisation. -O1 rather than
# -O3 took a fifth off the tests' compile time (~160 s of CI's build on 2
# cores). Programs whose own code does heavy work (board rendering, textbook
# BA problems) say KEEP_OPTIMISED. The precompiled header is built at the
# tests' level (its macros, e.g. __OPTIMIZE__, must match its users').
function(facadeslam_test_optimisation target)
  if(FACADESLAM_SANITIZE)
    target_compile_options(${target} PRIVATE -O0)
  else()
    target_compile_options(${target} PRIVATE $<$<CONFIG:Release,RelWithDebInfo,MinSizeRel>:-O1>)
  endif()
endfunction()

if(FACADESLAM_BUILD_TESTS)
  add_library(facadeslam_test_deps INTERFACE)
  target_link_libraries(facadeslam_test_deps INTERFACE
    GTest::gtest GTest::gmock Ceres::ceres Eigen3::Eigen facadeslam::opencv spdlog::spdlog fmt::fmt)
  if(FACADESLAM_PCH)
    add_library(facadeslam_test_pch OBJECT ${PROJECT_SOURCE_DIR}/cmake/pch_anchor.cpp)
    target_link_libraries(facadeslam_test_pch PRIVATE facadeslam_options facadeslam_test_deps)
    facadeslam_test_optimisation(facadeslam_test_pch)
    target_precompile_headers(facadeslam_test_pch PRIVATE
      <algorithm> <cmath> <filesystem> <memory> <string> <vector>
      <gtest/gtest.h> <gmock/gmock.h> <Eigen/Core> <Eigen/Geometry> <opencv2/core.hpp> <ceres/ceres.h>)
  endif()
endif()

#
# TRAINS_FORESTS: the program trains random forests (OpenCV's RTrees). RTrees
# allocates and frees large buffers per tree node; under ASan each is a fresh
# mapping whose shadow is faulted in 4 KiB pages, which made these programs
# 4-40x slower than the others under ASan (a page fault is dear on this
# kind of virtual machine). Huge pages for the shadow there cut
# test_semantics_labels from 45 to 7 s; everywhere they would slow the many
# short processes (0.59 -> 0.87 s to start `facadeslam --help`).
#
# FIXTURES names CTest fixtures every discovered test requires (e.g. a
# set-up test that clears a cache shared by the test processes). RUNS_APP:
# the tests run the built `facadeslam` binary, whose path they get as
# FACADESLAM_BINARY (and the program is built after it). KEEP_OPTIMISED: see
# facadeslam_test_optimisation above.
function(facadeslam_test name)
  cmake_parse_arguments(ARG "RUNS_APP;KEEP_OPTIMISED;RUN_SERIAL;TRAINS_FORESTS" "LABEL" "SOURCES;DEPS;FIXTURES" ${ARGN})
  if(NOT ARG_LABEL)
    set(ARG_LABEL unit)
  endif()
  # The sanitizer builds run the unit tests only (CI): the regression
  # programs would be built for nothing.
  if(FACADESLAM_SANITIZE AND ARG_LABEL STREQUAL "regression")
    return()
  endif()
  add_executable(${name} ${ARG_SOURCES})
  # fs_test_main (tests/support): gtest's main with an exit code for "all
  # skipped", which CTest reads through SKIP_RETURN_CODE below.
  target_link_libraries(${name} PRIVATE facadeslam_options ${ARG_DEPS} facadeslam_test_deps fs_test_main)
  if(ARG_RUNS_APP)
    target_compile_definitions(${name} PRIVATE FACADESLAM_BINARY="$<TARGET_FILE:facadeslam>")
    add_dependencies(${name} facadeslam)
  endif()
  # A KEEP_OPTIMISED program is compiled like the libraries, so it cannot use
  # the tests' precompiled header.
  if(NOT ARG_KEEP_OPTIMISED)
    facadeslam_test_optimisation(${name})
    if(FACADESLAM_PCH)
      target_precompile_headers(${name} REUSE_FROM facadeslam_test_pch)
    endif()
  endif()
  set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests)
  if(FACADESLAM_SANITIZE)
    # One CTest test per program: a sanitized process takes ~1 s to start
    # (shadow memory, OpenCV and Ceres loaded), which over ~770 test cases
    # was a third of CI's sanitizer stage. Every case still runs; a failure
    # names the case in the program's output.
    add_test(NAME ${name} COMMAND ${name} WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
    set_tests_properties(${name} PROPERTIES ENVIRONMENT "FACADESLAM_SOURCE_DIR=${PROJECT_SOURCE_DIR}"
                                            LABELS ${ARG_LABEL} FIXTURES_REQUIRED "${ARG_FIXTURES}"
                                            SKIP_RETURN_CODE 77)
    if(ARG_TRAINS_FORESTS AND FACADESLAM_SANITIZE STREQUAL "address")
      set_tests_properties(${name} PROPERTIES
        ENVIRONMENT_MODIFICATION "ASAN_OPTIONS=string_append::no_huge_pages_for_shadow=0")
    endif()
  else()
    # Properties only when given: an empty FIXTURES_REQUIRED would swallow the
    # next property name. RUN_SERIAL: the program's tests run alone (threaded,
    # timing-sensitive runs).
    set(properties ENVIRONMENT "FACADESLAM_SOURCE_DIR=${PROJECT_SOURCE_DIR}" LABELS ${ARG_LABEL} SKIP_RETURN_CODE 77)
    if(ARG_FIXTURES)
      list(APPEND properties FIXTURES_REQUIRED "${ARG_FIXTURES}")
    endif()
    if(ARG_RUN_SERIAL)
      list(APPEND properties RUN_SERIAL TRUE)
    endif()
    if(ARG_LABEL STREQUAL "regression")
      # One test per case: each is a whole SLAM run of up to ~40 s, and
      # per case they spread over the cores. A clean clone has no
      # CTestCostData.txt: without a cost they would start in file order, and
      # the last of them would keep one core busy while the other idles.
      list(APPEND properties COST 1000)
      gtest_discover_tests(${name}
        WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
        DISCOVERY_MODE PRE_TEST
        PROPERTIES ${properties})
    else()
      # One test per suite (cmake/TestSuiteDiscovery.cmake): unit cases take
      # milliseconds, their process start-up most of a second's tenth. The
      # property values must not hold a ';'.
      facadeslam_discover_test_suites(${name}
        WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
        PROPERTIES ${properties})
    endif()
  endif()
endfunction()

# facadeslam_bench(NAME SOURCES ... DEPS ...): one Google Benchmark program.
function(facadeslam_bench name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE facadeslam_options ${ARG_DEPS} benchmark::benchmark)
  set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/bench)
endfunction()
