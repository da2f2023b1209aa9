# cmake -DSNAPSHOT_BENCH=<snapshot_bench> -DWORK_DIR=<dir> -P SnapshotBenchSmoke.cmake
# Runs snapshot_bench on a small scene and checks what it writes, not how fast anything is: the JSON parses, has one
# row with positive times and size, and command-line errors exit with status 2.
cmake_policy(VERSION 3.25)
include(${CMAKE_CURRENT_LIST_DIR}/BenchSmoke.cmake)
bench_smoke_fresh_dir()
bench_smoke_run("${SNAPSHOT_BENCH}" "${WORK_DIR}/snapshots.json" "\\| scene \\| step ms \\|"
  --scene pyramid20 --steps 5 --repeats 2 --json "${WORK_DIR}/snapshots.json")
set(text "${bench_json}")
string(JSON rows ERROR_VARIABLE jerr LENGTH "${text}")
if(jerr OR NOT rows EQUAL 1)
  message(FATAL_ERROR "expected a JSON list of 1 row (${jerr}):\n${text}")
endif()
foreach(field step_ms snapshot_ms restore_ms snapshot_mb file_mb write_ms read_ms timeline_step_ratio)
  bench_smoke_number("${text}" value 0 ${field})
  if(NOT value GREATER 0)
    message(FATAL_ERROR "${field} is ${value}")
  endif()
endforeach()
bench_smoke_usage_errors("${SNAPSHOT_BENCH}" "--steps 0" "--scene no_such_scene" "--frobnicate" "--json")
file(REMOVE_RECURSE "${WORK_DIR}")
