# physim_find_root_wheel(<variable>): sets <variable> to the directory holding ROOTConfig.cmake of the ROOT wheel
# that scripts/setup.sh installs (a virtual environment under the user's cache, scripts/common.sh says where),
# or leaves it unset when there is none. Used by physim's build and by its installed package, so an installed
# physim finds the ROOT of the machine it is used on, never a path of the machine that built it.
function(physim_find_root_wheel variable)
  if(DEFINED ENV{PHYSIM_DEPS_DIR})
    set(deps "$ENV{PHYSIM_DEPS_DIR}")
  elseif(DEFINED ENV{XDG_CACHE_HOME})
    set(deps "$ENV{XDG_CACHE_HOME}/physim")
  else()
    set(deps "$ENV{HOME}/.cache/physim")
  endif()
  file(GLOB dirs "${deps}/root-venv/lib/python3*/site-packages/ROOT/cmake")
  if(dirs)
    list(GET dirs 0 dir)
    set(${variable} "${dir}" PARENT_SCOPE)
  endif()
endfunction()

# physim_root_wheel_link_dir(<variable> <ROOT_DIR>): the wheel bundles libraries (bz2, freetype, ...) in
# site-packages/root.libs, found at run time through RPATH; the linker must be told where they are when it links
# an executable. Sets <variable> to that folder, or leaves it unset for a ROOT that is not the wheel.
function(physim_root_wheel_link_dir variable root_dir)
  get_filename_component(libs "${root_dir}/../../root.libs" ABSOLUTE)
  if(IS_DIRECTORY "${libs}")
    set(${variable} "${libs}" PARENT_SCOPE)
  endif()
endfunction()

# physim_link_root_tbb(): the ROOT wheel carries its own oneTBB (libtbb.so.12, next to libCore.so), which its
# libraries need. A program that loads ROOT has that folder in its run path, so it runs the wheel's oneTBB
# whatever it was linked against, and the system's copy would only be a second libtbb.so.12 hidden behind it.
# Where ROOT has one, TBB::tbb is pointed at it: programs link the oneTBB they run (one per build; the system's
# headers are of an older release of the same ABI). Needs TBB::tbb and ROOT::Core; does nothing for a ROOT
# without a bundled oneTBB.
function(physim_link_root_tbb)
  if(NOT TARGET TBB::tbb OR NOT TARGET ROOT::Core)
    return()
  endif()
  get_target_property(root_configs ROOT::Core IMPORTED_CONFIGURATIONS)
  list(GET root_configs 0 root_config)
  get_target_property(root_core ROOT::Core IMPORTED_LOCATION_${root_config})
  get_filename_component(root_libs "${root_core}" DIRECTORY)
  if(NOT EXISTS "${root_libs}/libtbb.so.12")
    return()
  endif()
  get_target_property(tbb_configs TBB::tbb IMPORTED_CONFIGURATIONS)
  foreach(config IN LISTS tbb_configs)
    set_property(TARGET TBB::tbb PROPERTY IMPORTED_LOCATION_${config} "${root_libs}/libtbb.so.12")
  endforeach()
  set_property(TARGET TBB::tbb PROPERTY IMPORTED_LOCATION "${root_libs}/libtbb.so.12")
endfunction()
