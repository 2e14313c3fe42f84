# Helpers that give every vesica target the same warnings, conventions and install rules.
include(GNUInstallDirs)

# Warnings apply to our own sources only; third-party headers are SYSTEM includes.
function(vesica_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra)
endfunction()

# Tests and benchmarks build executables with the same helper; they are never installed.
function(vesica_is_shipped out)
  file(RELATIVE_PATH rel ${PROJECT_SOURCE_DIR} ${CMAKE_CURRENT_SOURCE_DIR})
  if(rel MATCHES "^(tests|bench)(/|$)")
    set(${out} OFF PARENT_SCOPE)
  else()
    set(${out} ON PARENT_SCOPE)
  endif()
endfunction()

# vesica_library(NAME SOURCES... DEPS ...): a stage or core library.
# Installed with its folder's public headers, include/**/*.h, and those configured from
# include/**/*.h.in into the same place under the binary folder (core's Version.h), and
# exported as vesica::<NAME without "vesica_"> (vesica_simulate -> vesica::simulate) in the
# package of cmake/vesicaConfig.cmake.in.
function(vesica_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_library(${name} STATIC ${ARG_SOURCES})
  target_include_directories(${name} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  file(GLOB_RECURSE configured RELATIVE ${CMAKE_CURRENT_SOURCE_DIR}/include
    ${CMAKE_CURRENT_SOURCE_DIR}/include/*.h.in)
  if(configured)
    target_include_directories(${name} PUBLIC
      $<BUILD_INTERFACE:${CMAKE_CURRENT_BINARY_DIR}/include>)
  endif()
  target_link_libraries(${name} PUBLIC ${ARG_DEPS})
  vesica_warnings(${name})

  vesica_is_shipped(shipped)
  if(NOT shipped)
    return()
  endif()
  string(REGEX REPLACE "^vesica_" "" export_name ${name})
  set_target_properties(${name} PROPERTIES EXPORT_NAME ${export_name})
  install(TARGETS ${name} EXPORT vesicaTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT Development)
  if(EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/include)
    install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
      COMPONENT Development FILES_MATCHING PATTERN "*.h" PATTERN "*.hpp")
  endif()
  foreach(template ${configured})
    string(REGEX REPLACE "\\.in$" "" header ${template})
    get_filename_component(folder ${header} DIRECTORY)
    install(FILES ${CMAKE_CURRENT_BINARY_DIR}/include/${header}
      DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/${folder} COMPONENT Development)
  endforeach()
endfunction()

# vesica_executable(NAME SOURCES... DEPS ...): a thin main, installed to bin/ (where the
# runner finds its stages, beside itself) unless it is a test's or a benchmark's.
function(vesica_executable name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS})
  vesica_warnings(${name})
  vesica_is_shipped(shipped)
  if(shipped)
    install(TARGETS ${name} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT Runtime)
  endif()
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
