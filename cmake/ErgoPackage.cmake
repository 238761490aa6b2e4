# The installable CMake package: `cmake --install build --prefix P` puts the headers under
# P/include, the static libraries under P/lib, the tools under P/bin and
# P/lib/cmake/ergo/ergoConfig.cmake with the exported targets (ergo::ergo, ergo::mesh, ...),
# so another project links ergo with `find_package(ergo CONFIG REQUIRED)`.
include(CMakePackageConfigHelpers)

foreach(folder ergo solvers problems)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${folder}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/${folder}
          FILES_MATCHING PATTERN "*.h")
endforeach()

set(ergo_config_dir ${CMAKE_INSTALL_LIBDIR}/cmake/ergo)
install(EXPORT ergoTargets NAMESPACE ergo:: DESTINATION ${ergo_config_dir})
# Dependencies the exported targets name beyond the fixed list in ergoConfig.cmake.in.
set(ERGO_EXTRA_DEPENDENCIES "")
if(TARGET nlohmann_json::nlohmann_json)
  string(APPEND ERGO_EXTRA_DEPENDENCIES "find_dependency(nlohmann_json 3.10)\n")
endif()
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/ergoConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/ergoConfig.cmake
                              INSTALL_DESTINATION ${ergo_config_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/ergoConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/ergoConfig.cmake ${PROJECT_BINARY_DIR}/ergoConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/FindCHOLMOD.cmake
        DESTINATION ${ergo_config_dir})
