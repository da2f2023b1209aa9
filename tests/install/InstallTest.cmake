# cmake -DBUILD_DIR=... -DWORK_DIR=... -DSOURCE_DIR=... -P InstallTest.cmake
# Installs the build into a scratch prefix, then configures, builds and runs the consumer project against it.
file(REMOVE_RECURSE "${WORK_DIR}")
execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${WORK_DIR}/prefix"
  RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "install failed: ${rc}")
endif()
# Relocatable: no path of this machine's ROOT in the installed package (the consumer finds its own).
get_filename_component(root_prefix "${ROOT_DIR}/../.." ABSOLUTE)  # the wheel's site-packages, or ROOT's prefix
file(GLOB_RECURSE package_files "${WORK_DIR}/prefix/*.cmake")
foreach(f IN LISTS package_files)
  file(READ "${f}" text)
  foreach(path IN ITEMS "${ROOT_DIR}" "${root_prefix}")
    string(FIND "${text}" "${path}" at)
    if(NOT at EQUAL -1)
      message(FATAL_ERROR "the installed ${f} names a path of the machine that built it: ${path}")
    endif()
  endforeach()
endforeach()
# The runner's internals stay out of the installed API (they live in src/framework).
foreach(internal IN ITEMS Controls FixedStepAccumulator PaceMeter Stats Summary)
  if(EXISTS "${WORK_DIR}/prefix/include/physim/framework/${internal}.hpp")
    message(FATAL_ERROR "the runner's internal ${internal}.hpp was installed")
  endif()
endforeach()
# Nor does the installed Runner.hpp name them: its tests reach them through RunnerAccess (src/framework).
file(READ "${WORK_DIR}/prefix/include/physim/framework/Runner.hpp" runner_header)
foreach(internal IN ITEMS Controls FixedStepAccumulator PaceMeter StepTimes)
  string(REGEX MATCH "[^A-Za-z_]${internal}[^A-Za-z_]" named "${runner_header}")
  if(named)
    message(FATAL_ERROR "the installed Runner.hpp names the runner's internal ${internal}")
  endif()
endforeach()
# Nor is the shared continuous kernel (src/core): the CUDA layer reaches it from the source tree.
if(EXISTS "${WORK_DIR}/prefix/include/physim/core/ContinuousKernel.hpp")
  message(FATAL_ERROR "the kernel's ContinuousKernel.hpp was installed")
endif()
# consume(NAME WHAT [PREFIX...]): configures, builds and runs the consumer project tests/install/NAME (its program
# is NAME) against the installed tree; PREFIX, if given, runs before cmake (an environment for the configure).
function(consume name what)
  execute_process(COMMAND ${ARGN} ${CMAKE_COMMAND} -S "${SOURCE_DIR}/tests/install/${name}" -B "${WORK_DIR}/${name}"
    -G Ninja -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix RESULT_VARIABLE rc)
  if(rc)
    message(FATAL_ERROR "${what} from the installed tree failed: ${rc}")
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} --build "${WORK_DIR}/${name}" RESULT_VARIABLE rc)
  if(rc)
    message(FATAL_ERROR "building ${name} against the installed physim failed: ${rc}")
  endif()
  execute_process(COMMAND "${WORK_DIR}/${name}/${name}" RESULT_VARIABLE rc)
  if(rc)
    message(FATAL_ERROR "the ${name} program failed: ${rc}")
  endif()
endfunction()
# No ROOT_DIR given: the package must find ROOT by itself.
consume(consumer "find_package(physim)")
# The core alone, by its component, with the ROOT wheel out of reach (an empty dependency folder): it must not
# need ROOT, SFML or X11.
file(MAKE_DIRECTORY "${WORK_DIR}/no-deps")
consume(core_consumer "find_package(physim COMPONENTS core)"
  ${CMAKE_COMMAND} -E env --unset=ROOT_DIR PHYSIM_DEPS_DIR=${WORK_DIR}/no-deps)
file(REMOVE_RECURSE "${WORK_DIR}")
