# Helpers that give every vesica target the same warnings, conventions and install rules.
include(GNUInstallDirs)
include(GoogleTest)

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

# The test tiers: every ctest entry carries exactly one of these labels (docs/CONVENTIONS.md,
# "Tests"). unit is the quick loop (`make check`); `make test` runs them all.
set(VESICA_TEST_TIERS unit acceptance fuzz install)

# vesica_tier_labels(OUT LABEL...): the labels, with unit added when they name no tier.
function(vesica_tier_labels out)
  set(labels ${ARGN})
  set(tiers ${labels})
  list(FILTER tiers INCLUDE REGEX "^(unit|acceptance|fuzz|install)$")
  list(LENGTH tiers count)
  if(count EQUAL 0)
    list(APPEND labels unit)
  elseif(count GREATER 1)
    message(FATAL_ERROR "labels ${labels} name more than one tier of ${VESICA_TEST_TIERS}")
  endif()
  set(${out} "${labels}" PARENT_SCOPE)
endfunction()

# vesica_test(NAME SOURCES... DEPS ... [LABELS ...] [ACCEPTANCE Suite|Suite.Case...]
#             [ONE_PROCESS Suite...] [TIMEOUT s] [COST c] [PROCESSORS n]): one GoogleTest
# binary. Each of its cases is its own ctest entry NAME.Suite.Case, listed from the binary
# after it links (gtest_discover_tests), so that `ctest -j` keeps every core busy and a
# failure names its case.
#   LABELS      the binary's tier (unit when none is named); the folder under tests/ (the
#               stage) is added as a label of its own.
#   ACCEPTANCE  suites (or single cases) of a unit binary that are acceptance tests
#               instead: the real CT, physiology, level 2, calibration, whole pipelines.
#   ONE_PROCESS suites that build something once for all their cases (SetUpTestSuite, a
#               static reference run): each stays one entry NAME.Suite, one process, so
#               that the work is neither repeated nor raced for by cases run at once.
#   TIMEOUT     seconds for one entry (600 when not given).
#   COST        a rough duration of one entry in seconds (acceptance: 10 when not given):
#               ctest starts costly entries first until it has timed them once itself.
#   PROCESSORS  cores one entry keeps busy (a case that runs two stages at once says 2).
function(vesica_test name)
  cmake_parse_arguments(ARG "" "TIMEOUT;COST;PROCESSORS"
    "SOURCES;DEPS;LABELS;ACCEPTANCE;ONE_PROCESS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS} GTest::gtest GTest::gtest_main)
  # A test binary's sources compiled a few at a time as one translation unit: GoogleTest,
  # the forced AssertionCount.h and the stage's headers are parsed once a batch instead of
  # once a source (the tests are nearly half of a clean build's compile time).
  if(VESICA_UNITY_TESTS)
    set_target_properties(${name} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 6)
  endif()
  vesica_warnings(${name})

  # The folder under tests/ (the stage) is a label too: `ctest -L simulate`.
  file(RELATIVE_PATH folder ${PROJECT_SOURCE_DIR}/tests ${CMAKE_CURRENT_SOURCE_DIR})
  string(REGEX REPLACE "/.*" "" folder "${folder}")
  vesica_tier_labels(labels ${ARG_LABELS} ${folder})
  list(REMOVE_DUPLICATES labels)
  set(acceptance_labels ${labels})
  list(TRANSFORM acceptance_labels REPLACE "^unit$" acceptance)
  # What every entry of the binary gets besides its labels: where it finds the shared real
  # data, the built executables and the sources (tests/support/TestData.h), its limits.
  set(environment "VESICA_SHARED_DIR=${VESICA_SHARED_DIR}" "VESICA_BIN_DIR=${CMAKE_BINARY_DIR}/bin"
    "VESICA_SOURCE_DIR=${CMAKE_SOURCE_DIR}")
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 600)
  endif()
  if(NOT ARG_PROCESSORS)
    set(ARG_PROCESSORS 1)
  endif()
  set(common TIMEOUT ${ARG_TIMEOUT} PROCESSORS ${ARG_PROCESSORS})
  set(acceptance_cost 10)
  if(ARG_COST)
    set(acceptance_cost ${ARG_COST})
  endif()
  set(cost "")  # of the binary's other entries
  if(ARG_COST OR "acceptance" IN_LIST labels)
    set(cost COST ${acceptance_cost})
  endif()

  set(one_process "")
  foreach(suite ${ARG_ONE_PROCESS})
    add_test(NAME ${name}.${suite} COMMAND ${name} --gtest_filter=${suite}.*)
    if(suite IN_LIST ARG_ACCEPTANCE)
      set_tests_properties(${name}.${suite} PROPERTIES LABELS "${acceptance_labels}"
        ENVIRONMENT "${environment}" ${common} COST ${acceptance_cost})
    else()
      set_tests_properties(${name}.${suite} PROPERTIES LABELS "${labels}"
        ENVIRONMENT "${environment}" ${common} ${cost})
    endif()
    list(APPEND one_process "${suite}.*")
  endforeach()
  set(filter "")
  if(one_process)
    list(JOIN one_process ":" joined)
    set(filter TEST_FILTER "-${joined}")
  endif()
  # NO_PRETTY_VALUES: a case named after its parameter keeps that name, without the printed
  # bytes of the parameter.
  gtest_discover_tests(${name} TEST_PREFIX ${name}. ${filter} TEST_LIST ${name}_cases
    NO_PRETTY_VALUES DISCOVERY_TIMEOUT 60)

  set(acceptance ${ARG_ACCEPTANCE})  # the one-process suites have no discovered case
  if(ARG_ONE_PROCESS)
    list(REMOVE_ITEM acceptance ${ARG_ONE_PROCESS})
  endif()
  vesica_write_case_properties(${name} "${labels}" "${acceptance_labels}" "${acceptance}"
    "${environment}" "${common}" "${cost}" ${acceptance_cost})
endfunction()

# The properties of the cases gtest_discover_tests finds, in a file ctest reads after their
# list NAME_cases: its own PROPERTIES option cannot carry a list (the labels, the
# environment), and the tier is chosen case by case.
function(vesica_write_case_properties name labels acceptance_labels acceptance environment
         common cost acceptance_cost)
  list(JOIN acceptance " " acceptance)
  list(JOIN common " " common)
  list(JOIN cost " " cost)
  file(CONFIGURE OUTPUT ${CMAKE_CURRENT_BINARY_DIR}/${name}_case_properties.cmake
    CONTENT [=[
# Generated by vesica_test (cmake/VesicaTargets.cmake) for @name@. LABELS adds to a test's
# labels: each case gets them once.
set(acceptance_cases "")
set(other_cases "")
# A suite or case named in ACCEPTANCE that matches no case (misspelt, renamed) fails a
# test of its own rather than leaving cases in the wrong tier unnoticed.
set(unmatched @acceptance@)
foreach(case IN LISTS @name@_cases)
  set(tier_of_case other_cases)
  foreach(item IN ITEMS @acceptance@)
    if(case MATCHES "^@name@\\.([^.]*/)?${item}(\\.|/|$)")
      set(tier_of_case acceptance_cases)
      list(REMOVE_ITEM unmatched ${item})
    endif()
  endforeach()
  list(APPEND ${tier_of_case} "${case}")
endforeach()
if(other_cases)
  set_tests_properties(${other_cases} PROPERTIES LABELS "@labels@"
    ENVIRONMENT "@environment@" @common@ @cost@)
endif()
if(acceptance_cases)
  set_tests_properties(${acceptance_cases} PROPERTIES LABELS "@acceptance_labels@"
    ENVIRONMENT "@environment@" @common@ COST @acceptance_cost@)
endif()
foreach(item IN LISTS unmatched)
  add_test(@name@.ACCEPTANCE_names_no_case_${item} /bin/false)
  set_tests_properties(@name@.ACCEPTANCE_names_no_case_${item} PROPERTIES LABELS "@labels@")
endforeach()
]=] @ONLY)
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES
    ${CMAKE_CURRENT_BINARY_DIR}/${name}_case_properties.cmake)
endfunction()

# vesica_test_case_properties(NAME Suite.Case PROPERTY VALUE...): ctest properties of one
# discovered case of vesica_test(NAME) (PROCESSORS 2 for a case that times two processes
# running at once). A case that no longer exists fails a test of its own.
function(vesica_test_case_properties name case)
  string(MAKE_C_IDENTIFIER "${case}" id)
  list(JOIN ARGN " " properties)
  file(CONFIGURE OUTPUT ${CMAKE_CURRENT_BINARY_DIR}/${name}_${id}_properties.cmake
    CONTENT [=[
list(FIND @name@_cases "@name@.@case@" index)  # ctest's scripts know no IN_LIST
if(index GREATER -1)
  set_tests_properties("@name@.@case@" PROPERTIES @properties@)
elseif(@name@_cases)
  add_test(@name@.case_properties_name_no_case_@id@ /bin/false)
  set_tests_properties(@name@.case_properties_name_no_case_@id@ PROPERTIES LABELS unit)
endif()
]=] @ONLY)
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES
    ${CMAKE_CURRENT_BINARY_DIR}/${name}_${id}_properties.cmake)
endfunction()
