# Installs the libraries, headers and a CMake package, so users write find_package(physim) and link
# physim::core, physim::graphs or physim::framework.
include(CMakePackageConfigHelpers)

set(_physim_targets physim_core)
if(PHYSIM_BUILD_FRAMEWORK)
  list(APPEND _physim_targets physim_graphs physim_framework)
endif()
if(PHYSIM_WITH_CUDA)
  list(APPEND _physim_targets physim_cuda)
endif()

install(TARGETS ${_physim_targets} EXPORT physimTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY include/physim DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT physimTargets NAMESPACE physim:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/physim)

set(PHYSIM_PACKAGE_WITH_FRAMEWORK ${PHYSIM_BUILD_FRAMEWORK})
configure_package_config_file(cmake/physimConfig.cmake.in ${PROJECT_BINARY_DIR}/physimConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/physim)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/physimConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/physimConfig.cmake ${PROJECT_BINARY_DIR}/physimConfigVersion.cmake
  ${PROJECT_SOURCE_DIR}/cmake/PhysimRootWheel.cmake
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/physim)
