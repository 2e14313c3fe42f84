# Helpers that give every vesica target the same warnings and conventions.

# Warnings apply to our own sources only; third-party headers are SYSTEM includes.
function(vesica_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra)
endfunction()

# vesica_library(NAME SOURCES... DEPS ...): a stage or core library.
function(vesica_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_library(${name} STATIC ${ARG_SOURCES})
  target_include_directories(${name} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include)
  target_link_libraries(${name} PUBLIC ${ARG_DEPS})
  vesica_warnings(${name})
endfunction()

# vesica_executable(NAME SOURCES... DEPS ...): a thin main.
function(vesica_executable name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS})
  vesica_warnings(${name})
endfunction()

# vesica_test(NAME SOURCES... DEPS ... [LABELS ...] [TIMEOUT s]): one GoogleTest binary,
# registered as one ctest test (fast start, one process) with the shared-data folder and
# the binary folder in its environment.
function(vesica_test name)
  cmake_parse_arguments(ARG "" "TIMEOUT" "SOURCES;DEPS;LABELS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS} GTest::gtest GTest::gtest_main)
  vesica_warnings(${name})
  add_test(NAME ${name} COMMAND ${name})
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 600)
  endif()
  set_tests_properties(${name} PROPERTIES TIMEOUT ${ARG_TIMEOUT}
    LABELS "${ARG_LABELS}"
    ENVIRONMENT "VESICA_SHARED_DIR=${VESICA_SHARED_DIR};VESICA_BIN_DIR=${CMAKE_BINARY_DIR}/bin;VESICA_SOURCE_DIR=${CMAKE_SOURCE_DIR}")
endfunction()
