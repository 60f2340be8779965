# Installs headers, libraries and a CMake package so that find_package(sinew) works.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# Public headers only: internal/ folders hold implementation headers (pugixml and the like).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/sinew/ DESTINATION include/sinew
  FILES_MATCHING PATTERN "*.h" PATTERN "internal" EXCLUDE)
install(TARGETS sinew ${SINEW_LAYER_TARGETS} EXPORT sinewTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION include)
install(TARGETS sinew_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(EXPORT sinewTargets NAMESPACE sinew:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/sinew)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/sinewConfig.cmake.in
  ${PROJECT_BINARY_DIR}/sinewConfig.cmake INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/sinew)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/sinewConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/sinewConfig.cmake ${PROJECT_BINARY_DIR}/sinewConfigVersion.cmake
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/sinew)
