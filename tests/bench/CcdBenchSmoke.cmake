# cmake -DCCD_BENCH=<ccd_bench> -DWORK_DIR=<dir> -P CcdBenchSmoke.cmake
# Runs ccd_bench's crowd mode on a tiny setting (10 bullets, 3 steps) and checks what it writes, not how fast
# anything is: the JSON has every key as a number, the bullet count is the one asked for, the escape counts lie
# in [0, bullets], and command-line errors exit with status 2 and a message.
cmake_policy(VERSION 3.25)
include(${CMAKE_CURRENT_LIST_DIR}/BenchSmoke.cmake)
bench_smoke_fresh_dir()
bench_smoke_run("${CCD_BENCH}" "${WORK_DIR}/crowd.json" "\\| detection \\| ms per step \\|"
  --crowd 10 --steps 3 --json "${WORK_DIR}/crowd.json")
foreach(key bullets steps exact_ms_per_step discrete_ms_per_step escaped discrete_escaped)
  bench_smoke_number("${bench_json}" ${key} ${key})
endforeach()
if(NOT bullets EQUAL 10 OR NOT steps EQUAL 3)
  message(FATAL_ERROR "asked for 10 bullets and 3 steps, the JSON says ${bullets} and ${steps}")
endif()
# if() compares numbers as doubles.
if(NOT exact_ms_per_step GREATER 0 OR NOT discrete_ms_per_step GREATER 0)
  message(FATAL_ERROR "a time is not positive: exact ${exact_ms_per_step}, discrete ${discrete_ms_per_step}")
endif()
foreach(count escaped discrete_escaped)
  if(${count} LESS 0 OR ${count} GREATER bullets)
    message(FATAL_ERROR "'${count}' is ${${count}}, outside [0, ${bullets}]")
  endif()
endforeach()
bench_smoke_usage_errors("${CCD_BENCH}" "--crowd 0" "--crowd ten" "--crowd 10 --steps" "--steps 3"
  "--crowd 10 --frobnicate 1")
file(REMOVE_RECURSE "${WORK_DIR}")
