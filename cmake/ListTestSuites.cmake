# Run by CTest (see TestSuiteDiscovery.cmake): lists a Google Test program's
# suites and writes the CTest file that registers one test per suite.

# facadeslam_list_suites(TARGET EXECUTABLE WORKING_DIRECTORY OUT PROPERTIES)
function(facadeslam_list_suites target executable working_directory out properties)
  execute_process(COMMAND "${executable}" --gtest_list_tests
                  WORKING_DIRECTORY "${working_directory}"
                  OUTPUT_VARIABLE listing ERROR_VARIABLE errors RESULT_VARIABLE status
                  TIMEOUT 60)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${executable} --gtest_list_tests failed (${status}): ${errors}")
  endif()
  # A suite line starts in column one and ends with '.', possibly followed by
  # "  # TypeParam = ..."; its cases are indented.
  string(REPLACE "\n" ";" lines "${listing}")
  set(suites "")
  foreach(line IN LISTS lines)
    # A disabled suite (DISABLED_..., also after an instantiation's
    # prefix) runs nothing unless asked for: it gets no test.
    if(line MATCHES "^([^ #][^ ]*)\\.( .*)?$")
      set(suite "${CMAKE_MATCH_1}")
      if(NOT suite MATCHES "(^|/)DISABLED_")
        list(APPEND suites "${suite}")
      endif()
    endif()
  endforeach()
  if(NOT suites)
    message(FATAL_ERROR "${executable} lists no test suite")
  endif()
  set(content "")
  foreach(suite IN LISTS suites)
    set(name "${target}:${suite}")
    string(APPEND content
      "add_test([==[${name}]==] [==[${executable}]==] [==[--gtest_filter=${suite}.*]==])\n"
      "set_tests_properties([==[${name}]==] PROPERTIES WORKING_DIRECTORY [==[${working_directory}]==]")
    # The properties come as NAME VALUE pairs.
    set(is_name TRUE)
    foreach(item IN LISTS properties)
      if(is_name)
        string(APPEND content " ${item}")
        set(is_name FALSE)
      else()
        string(APPEND content " [==[${item}]==]")
        set(is_name TRUE)
      endif()
    endforeach()
    string(APPEND content ")\n")
  endforeach()
  file(WRITE "${out}.tmp" "${content}")
  file(RENAME "${out}.tmp" "${out}")
endfunction()
