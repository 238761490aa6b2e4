# Helpers that keep each pipeline stage a separate library with its own test binary,
# so `ctest -R Stage` runs one stage and a broken stage does not stop the others building.

# ergo_stage_library(NAME DEPENDS dep...): a static library from every .cc in the
# current folder (and its subfolders), named ergo_NAME_lib (the tools own the plain names).
function(ergo_stage_library name)
  cmake_parse_arguments(ARG "" "" "DEPENDS" ${ARGN})
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cc)
  add_library(ergo_${name}_lib STATIC ${sources})
  target_link_libraries(ergo_${name}_lib PUBLIC ${ARG_DEPENDS})
  ergo_installed_library(ergo_${name}_lib ${name})
endfunction()

# ergo_installed_library(TARGET EXPORT_NAME): a library of the installed package, seen by
# consumers as ergo::EXPORT_NAME (ergoConfig.cmake); position-independent so that the
# Python module can link it.
function(ergo_installed_library target export_name)
  target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
                                              $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON
                                             EXPORT_NAME ${export_name})
  install(TARGETS ${target} EXPORT ergoTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endfunction()

# ergo_stage_tests(NAME LIBS lib...): one GoogleTest binary from tests/NAME/*.cc,
# every test case registered with CTest.
function(ergo_stage_tests name)
  cmake_parse_arguments(ARG "" "" "LIBS" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/${name}/*.cc)
  if(NOT sources)
    return()
  endif()
  add_executable(${name}_tests ${sources})
  target_link_libraries(${name}_tests PRIVATE ${ARG_LIBS} ergo_test_support GTest::gtest
                        GTest::gtest_main)
  gtest_discover_tests(${name}_tests
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
    DISCOVERY_TIMEOUT 60
    PROPERTIES ENVIRONMENT "ERGO_SOURCE_DIR=${PROJECT_SOURCE_DIR}")
endfunction()

# ergo_benchmark(NAME SOURCE LIBS lib...): a Google Benchmark program (never a test).
function(ergo_benchmark name source)
  cmake_parse_arguments(ARG "" "" "LIBS" ${ARGN})
  if(NOT ERGO_BUILD_BENCHMARKS)
    return()
  endif()
  add_executable(${name} ${source})
  target_link_libraries(${name} PRIVATE ${ARG_LIBS} benchmark::benchmark)
endfunction()
