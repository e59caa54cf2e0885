# `cmake --install BUILD [--prefix DIR]`: the headers (include/msmesh and io/include/msmesh, into
# <prefix>/include/msmesh), the static libraries msmesh_core and msmesh_io, the program msmesh,
# and the CMake package msmesh (<prefix>/lib/cmake/msmesh): find_package(msmesh) gives the
# targets msmesh::core and msmesh::io. Checked by the ctest entry install_consumer
# (tests/install/). The drawing library, the Python module, tests and benchmarks are not
# installed (the Python module installs with pip: docs/python.md).
include(CMakePackageConfigHelpers)

set(MSMESH_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/msmesh CACHE STRING
    "Where the CMake package msmesh (msmeshConfig.cmake) is installed, under the prefix")

install(TARGETS msmesh_core msmesh_io EXPORT msmeshTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS msmesh RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/msmesh ${PROJECT_SOURCE_DIR}/io/include/msmesh
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.h")

install(EXPORT msmeshTargets NAMESPACE msmesh:: DESTINATION ${MSMESH_INSTALL_CMAKEDIR})
set(MSMESH_EXPORT_OPENMP ${OpenMP_CXX_FOUND})
if(NOT MSMESH_EXPORT_OPENMP)
  set(MSMESH_EXPORT_OPENMP OFF)
endif()
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/msmeshConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/msmeshConfig.cmake
                              INSTALL_DESTINATION ${MSMESH_INSTALL_CMAKEDIR})
# 0.x: a new minor version may change the interface.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/msmeshConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/msmeshConfig.cmake ${PROJECT_BINARY_DIR}/msmeshConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/FindCHOLMOD.cmake
        DESTINATION ${MSMESH_INSTALL_CMAKEDIR})
