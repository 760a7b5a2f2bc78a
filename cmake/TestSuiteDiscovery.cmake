# facadeslam_discover_test_suites(TARGET WORKING_DIRECTORY DIR PROPERTIES ...):
# registers one CTest test per Google Test suite of TARGET, named
# "TARGET:Suite" and running `TARGET --gtest_filter=Suite.*`.
#
# Why not gtest_discover_tests' one test per case: each case is then its own
# process, and a program linking OpenCV spends ~0.15 s in the dynamic loader
# before its first test (Debian's imgcodecs loads GDAL and GDCM, ~146
# libraries). Over ~1100 unit cases that was a third of the test stage. A
# suite is still small enough to spread over the cores, and its output names
# the failing case.
#
# Like gtest_discover_tests' PRE_TEST mode the suites are listed when CTest
# runs (the program is run with --gtest_list_tests then, and again only when
# it is rebuilt), so configuring does not need the built programs.
set(_facadeslam_list_suites_script ${CMAKE_CURRENT_LIST_DIR}/ListTestSuites.cmake)

function(facadeslam_discover_test_suites target)
  cmake_parse_arguments(ARG "" "WORKING_DIRECTORY" "PROPERTIES" ${ARGN})
  set(base ${CMAKE_CURRENT_BINARY_DIR}/${target})
  set(suites_file ${base}_suites.cmake)
  # Properties travel as one ;-list in a bracket argument: values with
  # spaces stay whole.
  string(CONCAT include_content
    "if(EXISTS [==[$<TARGET_FILE:${target}>]==])\n"
    "  if(NOT EXISTS [==[${suites_file}]==] OR\n"
    "     NOT [==[${suites_file}]==] IS_NEWER_THAN [==[$<TARGET_FILE:${target}>]==] OR\n"
    "     NOT [==[${suites_file}]==] IS_NEWER_THAN \"\${CMAKE_CURRENT_LIST_FILE}\" OR\n"
    "     NOT [==[${suites_file}]==] IS_NEWER_THAN [==[${_facadeslam_list_suites_script}]==])\n"
    "    include([==[${_facadeslam_list_suites_script}]==])\n"
    "    facadeslam_list_suites([==[${target}]==] [==[$<TARGET_FILE:${target}>]==]\n"
    "      [==[${ARG_WORKING_DIRECTORY}]==] [==[${suites_file}]==] [==[${ARG_PROPERTIES}]==])\n"
    "  endif()\n"
    "  include([==[${suites_file}]==])\n"
    "else()\n"
    "  add_test([==[${target}_NOT_BUILT]==] [==[${target}_NOT_BUILT]==])\n"
    "endif()\n")
  file(GENERATE OUTPUT ${base}_suites_include.cmake CONTENT "${include_content}")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${base}_suites_include.cmake)
endfunction()
