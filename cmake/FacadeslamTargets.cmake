# Project-wide compile settings, applied per target so dependencies are not
# affected: strict warnings as errors, and the optional sanitizers.
add_library(facadeslam_options INTERFACE)
target_compile_options(facadeslam_options INTERFACE -Wall -Wextra -Wpedantic -Werror)
target_include_directories(facadeslam_options INTERFACE ${PROJECT_SOURCE_DIR})

if(FACADESLAM_SANITIZE STREQUAL "address")
  set(_fs_san -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
elseif(FACADESLAM_SANITIZE STREQUAL "thread")
  set(_fs_san -fsanitize=thread -fno-omit-frame-pointer)
elseif(NOT FACADESLAM_SANITIZE STREQUAL "")
  message(FATAL_ERROR "FACADESLAM_SANITIZE must be empty, 'address' or 'thread', not '${FACADESLAM_SANITIZE}'")
endif()
if(_fs_san)
  target_compile_options(facadeslam_options INTERFACE ${_fs_san} -g)
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
function(facadeslam_test name)
  cmake_parse_arguments(ARG "" "LABEL" "SOURCES;DEPS" ${ARGN})
  if(NOT ARG_LABEL)
    set(ARG_LABEL unit)
  endif()
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE facadeslam_options ${ARG_DEPS} GTest::gtest GTest::gtest_main GTest::gmock)
  set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests)
  gtest_discover_tests(${name}
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
    DISCOVERY_MODE PRE_TEST
    PROPERTIES ENVIRONMENT "FACADESLAM_SOURCE_DIR=${PROJECT_SOURCE_DIR}" LABELS ${ARG_LABEL})
endfunction()

# facadeslam_bench(NAME SOURCES ... DEPS ...): one Google Benchmark program.
function(facadeslam_bench name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE facadeslam_options ${ARG_DEPS} benchmark::benchmark)
  set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/bench)
endfunction()
