# physim_add_library(<target> <export name> <sources...>): one of physim's libraries, with the public include
# directory, exported (and installed) as physim::<export name>.
function(physim_add_library target export_name)
  add_library(${target} ${ARGN})
  add_library(physim::${export_name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${export_name} POSITION_INDEPENDENT_CODE ON)
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_features(${target} PUBLIC cxx_std_17)
endfunction()
