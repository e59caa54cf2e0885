# Finds SuiteSparse's CHOLMOD (Debian: libsuitesparse-dev; SuiteSparse 5 has no CMake package
# of its own) and defines the imported target CHOLMOD::CHOLMOD. Used by the build and, installed
# next to msmeshConfig.cmake, by find_package(msmesh): msmesh::core links it.
#   CHOLMOD_INCLUDE_DIR  the folder of cholmod.h
#   CHOLMOD_LIBRARY      the library
include(FindPackageHandleStandardArgs)
find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
find_library(CHOLMOD_LIBRARY cholmod)
find_package_handle_standard_args(CHOLMOD REQUIRED_VARS CHOLMOD_LIBRARY CHOLMOD_INCLUDE_DIR)
if(CHOLMOD_FOUND AND NOT TARGET CHOLMOD::CHOLMOD)
  add_library(CHOLMOD::CHOLMOD UNKNOWN IMPORTED)
  set_target_properties(CHOLMOD::CHOLMOD PROPERTIES IMPORTED_LOCATION "${CHOLMOD_LIBRARY}"
                                                    INTERFACE_INCLUDE_DIRECTORIES "${CHOLMOD_INCLUDE_DIR}")
endif()
mark_as_advanced(CHOLMOD_INCLUDE_DIR CHOLMOD_LIBRARY)
