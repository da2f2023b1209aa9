# cmake -DEFFECTS_BENCH=<effects_bench> -DWORK_DIR=<dir> -P EffectsBenchSmoke.cmake
# Runs effects_bench on one effect with one short round and checks what it writes, not how fast anything is: the
# JSON has the one row asked for with the fields docs/effects.md promises, every time positive; bad arguments
# exit with status 2 and a message.
cmake_policy(VERSION 3.25)
include(${CMAKE_CURRENT_LIST_DIR}/BenchSmoke.cmake)
bench_smoke_fresh_dir()
bench_smoke_run("${EFFECTS_BENCH}" "${WORK_DIR}/effects.json" "\\| effect \\| scene \\| used means \\|"
  --only drag --rounds 1 --steps 1 --json "${WORK_DIR}/effects.json")
if(NOT bench_stdout MATCHES "\\| drag \\|")
  message(FATAL_ERROR "no drag row on stdout:\n${bench_stdout}")
endif()
string(JSON rows ERROR_VARIABLE jerr LENGTH "${bench_json}")
if(jerr OR NOT rows EQUAL 1)
  message(FATAL_ERROR "expected a JSON array of one row (${jerr}):\n${bench_json}")
endif()
string(JSON effect GET "${bench_json}" 0 effect)
if(NOT effect STREQUAL "drag")
  message(FATAL_ERROR "the row is '${effect}', not drag")
endif()
foreach(field without_ms unused_ms used_ms unused_ratio used_ratio)
  bench_smoke_number("${bench_json}" value 0 ${field})
  if(NOT value GREATER 0)
    message(FATAL_ERROR "'${field}' is ${value}, not a positive time")
  endif()
endforeach()
bench_smoke_usage_errors("${EFFECTS_BENCH}" "--rounds 0" "--only no_such_effect" "--steps x" "--frobnicate" "--json")
file(REMOVE_RECURSE "${WORK_DIR}")
