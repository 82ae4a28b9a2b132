# relmap_compile_as_test(<target>): a target of test code (test cases, fixtures) at -O1
# in Release. It holds fixtures and assertions, and GoogleTest's and GoogleMock's
# templates cost a quarter less to compile than at -O3 (in_process_service_test.cpp:
# 10.8 s instead of 14.1 s). The code under test is in the libraries, at -O3 as shipped.
function(relmap_compile_as_test target)
  target_compile_options(${target} PRIVATE $<$<CONFIG:Release>:-O1>)
endfunction()

# relmap_add_gtest(<name> SOURCES <files...> LIBRARIES <targets...> [LABELS <labels...>])
# A GoogleTest executable registered with CTest test by test (gtest_discover_tests).
include(GoogleTest)
function(relmap_add_gtest name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBRARIES;LABELS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_LIBRARIES} GTest::gmock GTest::gtest_main relmap_warnings)
  target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR}/tests)
  relmap_compile_as_test(${name})
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60)
  # The labels are set by a CTest script of their own, read after the discovered tests:
  # given to gtest_discover_tests(PROPERTIES LABELS "unit;threads"), a list reaches
  # set_tests_properties split into words, so a test kept only the first label ("threads"
  # selected no test, and `scripts/sanitize.sh thread` ran none of the concurrent unit
  # programs), and no escaping of the semicolon survives the way there.
  if(ARG_LABELS)
    set(script "${CMAKE_CURRENT_BINARY_DIR}/${name}_labels.cmake")
    file(WRITE "${script}"
         "foreach(test IN LISTS ${name}_TESTS)\n"
         "  set_tests_properties(\"\${test}\" PROPERTIES LABELS \"${ARG_LABELS}\")\n"
         "endforeach()\n")
    set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${script}")
  endif()
endfunction()
