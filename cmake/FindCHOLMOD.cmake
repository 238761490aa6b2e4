# FindCHOLMOD: SuiteSparse's CHOLMOD has no CMake config on Debian 12.
# Provides the imported target CHOLMOD::CHOLMOD (headers in /usr/include/suitesparse,
# which Eigen's CholmodSupport also needs).
find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
find_library(CHOLMOD_LIBRARY cholmod)
find_library(SUITESPARSECONFIG_LIBRARY suitesparseconfig)
find_library(AMD_LIBRARY amd)
find_library(COLAMD_LIBRARY colamd)
find_library(CAMD_LIBRARY camd)
find_library(CCOLAMD_LIBRARY ccolamd)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(CHOLMOD REQUIRED_VARS CHOLMOD_LIBRARY CHOLMOD_INCLUDE_DIR
                                  SUITESPARSECONFIG_LIBRARY AMD_LIBRARY COLAMD_LIBRARY)
if(CHOLMOD_FOUND AND NOT TARGET CHOLMOD::CHOLMOD)
  add_library(CHOLMOD::CHOLMOD UNKNOWN IMPORTED)
  set_target_properties(CHOLMOD::CHOLMOD PROPERTIES
    IMPORTED_LOCATION "${CHOLMOD_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${CHOLMOD_INCLUDE_DIR}")
  target_link_libraries(CHOLMOD::CHOLMOD INTERFACE ${SUITESPARSECONFIG_LIBRARY} ${AMD_LIBRARY}
                        ${COLAMD_LIBRARY} ${CAMD_LIBRARY} ${CCOLAMD_LIBRARY})
endif()
mark_as_advanced(CHOLMOD_INCLUDE_DIR CHOLMOD_LIBRARY SUITESPARSECONFIG_LIBRARY AMD_LIBRARY
                 COLAMD_LIBRARY CAMD_LIBRARY CCOLAMD_LIBRARY)
