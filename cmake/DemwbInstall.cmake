# SPDX-License-Identifier: MIT
# `cmake --install` puts demwb, the core library demwb::dem with its headers, a CMake package
# config (find_package(demwb)) and the canonical cases in place.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(TARGETS demwb_dem EXPORT demwbTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/dem/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/dem
        FILES_MATCHING PATTERN "*.hpp")
install(EXPORT demwbTargets NAMESPACE demwb:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/demwb)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/demwbConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/demwbConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/demwb)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/demwbConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/demwbConfig.cmake ${PROJECT_BINARY_DIR}/demwbConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/demwb)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/cases/canonical ${PROJECT_SOURCE_DIR}/cases/baselines
        DESTINATION ${CMAKE_INSTALL_DATADIR}/demwb/cases OPTIONAL)
