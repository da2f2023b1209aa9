# What the bench smoke scripts share: each runs its program on a tiny setting and checks what it writes, never how
# fast anything is. include() it from a script run with cmake -P.

# An empty WORK_DIR for the run's files.
function(bench_smoke_fresh_dir)
  file(REMOVE_RECURSE "${WORK_DIR}")
  file(MAKE_DIRECTORY "${WORK_DIR}")
endfunction()

# bench_smoke_run(<program> <json file> <table regex> <arguments...>): runs the program, fails unless it exits 0
# and prints a table matching the regex; sets bench_stdout and bench_json (the file's text) in the caller.
function(bench_smoke_run program json table)
  get_filename_component(name "${program}" NAME)
  execute_process(COMMAND "${program}" ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(rc)
    message(FATAL_ERROR "${name} failed (${rc}):\n${out}\n${err}")
  endif()
  if(NOT out MATCHES "${table}")
    message(FATAL_ERROR "${name} printed no table matching '${table}':\n${out}")
  endif()
  file(READ "${json}" text)
  set(bench_stdout "${out}" PARENT_SCOPE)
  set(bench_json "${text}" PARENT_SCOPE)
endfunction()

# bench_smoke_number(<json text> <variable> <path...>): the number at the JSON path, failing if it is not one.
function(bench_smoke_number text variable)
  string(JSON type ERROR_VARIABLE jerr TYPE "${text}" ${ARGN})
  if(jerr OR NOT type STREQUAL "NUMBER")
    message(FATAL_ERROR "'${ARGN}' is missing or not a number (${type} ${jerr}):\n${text}")
  endif()
  string(JSON value GET "${text}" ${ARGN})
  set(${variable} "${value}" PARENT_SCOPE)
endfunction()

# bench_smoke_usage_errors(<program> <command line>...): each command line (a string, split like a shell's) must
# make the program exit with status 2 and a message that names it.
function(bench_smoke_usage_errors program)
  get_filename_component(name "${program}" NAME)
  foreach(line IN LISTS ARGN)
    separate_arguments(arguments UNIX_COMMAND "${line}")
    execute_process(COMMAND "${program}" ${arguments} RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
    if(NOT rc EQUAL 2 OR NOT err MATCHES "${name}: ")
      message(FATAL_ERROR "${name} ${line} exited ${rc}, expected 2 with a message:\n${err}")
    endif()
  endforeach()
endfunction()
