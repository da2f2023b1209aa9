# Finds physim's dependencies. scripts/setup.sh installs them; ROOT comes from its PyPI wheel in a venv.

find_package(Eigen3 3.4 REQUIRED NO_MODULE)
# oneTBB: the step's worker threads (src/core/Executor.hpp). Found here, for the whole tree, since the ROOT wheel
# below may supply the library that programs run (physim_link_root_tbb).
find_package(TBB REQUIRED)

if(PHYSIM_BUILD_FRAMEWORK)
  find_package(SFML 2.5 REQUIRED COMPONENTS graphics window system)
  find_package(X11 REQUIRED)
  find_package(nlohmann_json 3.10 REQUIRED)

  # The ROOT wheel lives in a virtual environment outside the build tree (scripts/common.sh says where).
  include(PhysimRootWheel)
  if(NOT ROOT_DIR AND NOT DEFINED ENV{ROOT_DIR})
    physim_find_root_wheel(_physim_root_dir)
    if(_physim_root_dir)
      set(ROOT_DIR "${_physim_root_dir}" CACHE PATH "Directory with ROOTConfig.cmake")
    endif()
  endif()
  find_package(ROOT 6.30 CONFIG REQUIRED COMPONENTS Core Hist Gpad Graf RIO Tree)
  physim_root_wheel_link_dir(PHYSIM_ROOT_LIBS_DIR "${ROOT_DIR}")
  physim_link_root_tbb()
endif()

if(PHYSIM_BUILD_TESTS)
  find_package(GTest REQUIRED)
  include(GoogleTest)
endif()
if(PHYSIM_BUILD_BENCHMARKS)
  find_package(benchmark REQUIRED)
  # Optional: the peer engine bench/peers measures physim against; without it peer_bench runs physim alone.
  find_package(box2d 2.4 CONFIG QUIET)
  if(box2d_FOUND)
    message(STATUS "peer_bench: Box2D ${box2d_VERSION} found")
  else()
    message(STATUS "peer_bench: Box2D 2.4 not found (libbox2d-dev), physim only")
  endif()
endif()
