# Installs the libraries, headers and a CMake package with one component per library:
#   find_package(physim REQUIRED COMPONENTS core)       -> physim::core (Eigen; the static core also links
#                                                         oneTBB)
#   find_package(physim REQUIRED COMPONENTS framework)  -> physim::framework and physim::graphs (SFML, X11, ROOT)
# A component looks only for its own dependencies; find_package(physim) with none loads every installed one.
include(CMakePackageConfigHelpers)

set(_physim_package_dir ${CMAKE_INSTALL_LIBDIR}/cmake/physim)

# physim_install_component(<component> <target>): the library, its headers (include/physim/<component>) and its
# own export file, physim_<component>Targets.cmake, which physimConfig.cmake loads when the component is asked for.
function(physim_install_component component target)
  install(TARGETS ${target} EXPORT physim_${component}Targets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(DIRECTORY include/physim/${component} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/physim)
  install(EXPORT physim_${component}Targets NAMESPACE physim:: DESTINATION ${_physim_package_dir})
endfunction()

set(PHYSIM_PACKAGE_COMPONENTS core)
physim_install_component(core physim_core)
if(PHYSIM_WITH_CUDA)
  list(APPEND PHYSIM_PACKAGE_COMPONENTS cuda)
  physim_install_component(cuda physim_cuda)
endif()
if(PHYSIM_BUILD_FRAMEWORK)
  list(APPEND PHYSIM_PACKAGE_COMPONENTS graphs framework)
  physim_install_component(graphs physim_graphs)
  physim_install_component(framework physim_framework)
  install(FILES ${PROJECT_SOURCE_DIR}/cmake/PhysimRootWheel.cmake DESTINATION ${_physim_package_dir})
endif()

configure_package_config_file(cmake/physimConfig.cmake.in ${PROJECT_BINARY_DIR}/physimConfig.cmake
  INSTALL_DESTINATION ${_physim_package_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/physimConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/physimConfig.cmake ${PROJECT_BINARY_DIR}/physimConfigVersion.cmake
  DESTINATION ${_physim_package_dir})
