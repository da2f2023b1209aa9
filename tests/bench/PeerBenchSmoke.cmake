# cmake -DPEER_BENCH=<peer_bench> -DWORK_DIR=<dir> -DPEER=<peer engine name or empty> -P PeerBenchSmoke.cmake
# Runs peer_bench on a tiny setting and checks what it writes, not how fast anything is: the JSON parses, has
# one row per engine with every field the table promises, the body count is the pyramid's N (N + 1) / 2, every
# engine keeps chain_terrain's bodies on its chain, every engine's cars drive, Box2D v3's scenes run, and command-line
# errors exit with status 2.
cmake_policy(VERSION 3.25)
include(${CMAKE_CURRENT_LIST_DIR}/BenchSmoke.cmake)
bench_smoke_fresh_dir()
bench_smoke_run("${PEER_BENCH}" "${WORK_DIR}/peers.json" "\\| scene \\| engine \\| threads \\| bodies \\|"
  --scenes pyramid20 --repeats 2 --steps 110 --json "${WORK_DIR}/peers.json")
set(text "${bench_json}")
string(JSON rows ERROR_VARIABLE jerr LENGTH "${text}")
if(jerr)
  message(FATAL_ERROR "the JSON does not parse: ${jerr}\n${text}")
endif()
# physim with 1 thread, with every hardware thread when there are several, and the peer when built with one.
set(fewest 1)
if(PEER)
  set(fewest 2)
endif()
math(EXPR most "${fewest} + 1")
if(rows LESS fewest OR rows GREATER most)
  message(FATAL_ERROR "expected ${fewest} or ${most} rows, got ${rows}:\n${text}")
endif()

set(engines "")
math(EXPR last "${rows} - 1")
foreach(i RANGE ${last})
  foreach(field scene engine threads bodies ms_per_step_min ms_per_step_median top_drop top_drift max_sideways)
    string(JSON type ERROR_VARIABLE jerr TYPE "${text}" ${i} ${field})
    if(jerr)
      message(FATAL_ERROR "row ${i} has no '${field}': ${jerr}")
    endif()
    set(want NUMBER)
    if(field STREQUAL "scene" OR field STREQUAL "engine")
      set(want STRING)
    endif()
    if(NOT type STREQUAL want)
      message(FATAL_ERROR "row ${i}: '${field}' is ${type}, not ${want}")
    endif()
    string(JSON row_${field} GET "${text}" ${i} ${field})
  endforeach()
  if(NOT row_scene STREQUAL "pyramid20" OR NOT row_bodies EQUAL 210)
    message(FATAL_ERROR "row ${i}: scene '${row_scene}' with ${row_bodies} bodies, expected pyramid20 with 20 * 21 / 2 = 210")
  endif()
  # if() compares numbers as doubles. The min of the repeats is at most their median.
  if(NOT row_ms_per_step_min GREATER 0 OR row_ms_per_step_min GREATER row_ms_per_step_median)
    message(FATAL_ERROR "row ${i}: min ${row_ms_per_step_min} ms and median ${row_ms_per_step_median} ms")
  endif()
  if(row_top_drift LESS 0 OR row_max_sideways LESS 0)
    message(FATAL_ERROR "row ${i}: a distance is negative (drift ${row_top_drift}, sideways ${row_max_sideways})")
  endif()
  list(APPEND engines "${row_engine}:${row_threads}")
endforeach()
foreach(want "physim:1" ${PEER})
  if(NOT want IN_LIST engines)
    message(FATAL_ERROR "no row for ${want} (rows: ${engines})")
  endif()
endforeach()

# --substeps adds a one-thread physim row per count, kept by --engines physim, and a line fitted through the
# substep counts that ran (the default's and this one): two points, so the line exists; its values are noise here.
bench_smoke_run("${PEER_BENCH}" "${WORK_DIR}/substeps.json" "\\| physim-substeps4 \\| 1 \\| 210 \\|"
  --scenes pyramid20 --engines physim --substeps 4 --repeats 1 --steps 110 --json "${WORK_DIR}/substeps.json")
string(JSON rows LENGTH "${bench_json}")
math(EXPR last "${rows} - 1")
string(JSON last_engine GET "${bench_json}" ${last} engine)
string(JSON last_threads GET "${bench_json}" ${last} threads)
if(NOT last_engine STREQUAL "physim-substeps4" OR NOT last_threads EQUAL 1)
  message(FATAL_ERROR "the last row is ${last_engine} on ${last_threads} threads, not physim-substeps4 on 1:\n${bench_json}")
endif()
if(NOT bench_stdout MATCHES "pyramid20: -?[0-9.]+ ms per step \\+ -?[0-9.]+ ms per substep \\(2 runs, 4\\.\\.[0-9]+ substeps\\)")
  message(FATAL_ERROR "no fit of step time against substeps:\n${bench_stdout}")
endif()

# chain_terrain: no body through the chain, none sunk into it past 1 cm (a resting body reads 0 less its overlap,
# a few millimetres at most at the slop), and the check's lines printed. 120 steps: the bodies have landed by 60.
bench_smoke_run("${PEER_BENCH}" "${WORK_DIR}/chain.json" "\\| chain_terrain \\| physim \\| 1 \\| 600 \\|"
  --scenes chain_terrain --repeats 1 --steps 120 --json "${WORK_DIR}/chain.json")
if(NOT bench_stdout MATCHES "chain_terrain physim x1: lowest -?[0-9.]+, 0 of 600 below the chain")
  message(FATAL_ERROR "no ground check line for physim:\n${bench_stdout}")
endif()
string(JSON rows LENGTH "${bench_json}")
math(EXPR last "${rows} - 1")
foreach(i RANGE ${last})
  bench_smoke_number("${bench_json}" below ${i} below_ground)
  bench_smoke_number("${bench_json}" lowest ${i} min_clearance)
  string(JSON engine GET "${bench_json}" ${i} engine)
  if(NOT below EQUAL 0 OR lowest LESS -0.01)
    message(FATAL_ERROR "${engine}: ${below} bodies below the chain, the lowest ${lowest} m above it less its radius")
  endif()
endforeach()

# joint_grid: the net hangs from its top row (101 steps, 1.7 s): every engine's lowest disc is a number, below its
# start at -99 m (the joints stretch a little under the net's weight), and above -200 m (no joint came apart), and
# the lines under the table printed.
bench_smoke_run("${PEER_BENCH}" "${WORK_DIR}/joints.json" "\\| joint_grid \\| physim \\| 1 \\| 9993 \\|"
  --scenes joint_grid --repeats 1 --steps 101 --json "${WORK_DIR}/joints.json")
if(NOT bench_stdout MATCHES "joint_grid physim x1: -[0-9.]+ \\(from -99\\.000\\)")
  message(FATAL_ERROR "no lowest-disc line for physim:\n${bench_stdout}")
endif()
string(JSON rows LENGTH "${bench_json}")
math(EXPR last "${rows} - 1")
foreach(i RANGE ${last})
  bench_smoke_number("${bench_json}" lowest ${i} lowest_y)
  string(JSON engine GET "${bench_json}" ${i} engine)
  if(NOT lowest LESS -99 OR lowest LESS -200)
    message(FATAL_ERROR "${engine}: the lowest disc of joint_grid at ${lowest} m")
  endif()
endforeach()

# cars: 60 cars land on their chain and drive right (120 steps, 2 s): every engine's cars moved right on average by
# more than 1 m (from rest, they reach about 4 m/s within a second), all stay upright, none fell through the chain,
# and the line under the table printed.
bench_smoke_run("${PEER_BENCH}" "${WORK_DIR}/cars.json" "\\| cars \\| physim \\| 1 \\| 180 \\|"
  --scenes cars --repeats 1 --steps 120 --json "${WORK_DIR}/cars.json")
if(NOT bench_stdout MATCHES "cars physim x1: mean dx [0-9.]+, 60 of 60 upright")
  message(FATAL_ERROR "no cars line for physim:\n${bench_stdout}")
endif()
string(JSON rows LENGTH "${bench_json}")
math(EXPR last "${rows} - 1")
foreach(i RANGE ${last})
  bench_smoke_number("${bench_json}" dx ${i} cars_mean_dx)
  bench_smoke_number("${bench_json}" upright ${i} cars_upright)
  bench_smoke_number("${bench_json}" below ${i} below_ground)
  string(JSON engine GET "${bench_json}" ${i} engine)
  if(NOT dx GREATER 1 OR NOT upright EQUAL 60 OR NOT below EQUAL 0)
    message(FATAL_ERROR "${engine}: cars moved ${dx} m, ${upright} of 60 upright, ${below} bodies below the chain")
  endif()
endforeach()

# Box2D v3's benchmark scenes that were not here before (101 steps, 1.7 s, one repeat: that they build and run in
# every engine, not how they end): one row per engine and scene with the scene's body count (spinner and tumbler
# count their turning bar or drum), but none for Box2D 2.4.1 on junkyard, spinner and washer, which it does not run
# (a note says why). tumbler: no box below the drum's lowest inner corner, which has turned 42 degrees to 10 - 9.5 sqrt(2)
# cos(3 degrees) = -3.42 m.
bench_smoke_run("${PEER_BENCH}" "${WORK_DIR}/v3.json" "\\| washer \\| physim \\| 1 \\| 8100 \\|"
  --scenes compounds,junkyard,rain,spinner,tumbler,washer --repeats 1 --steps 101 --json "${WORK_DIR}/v3.json")
set(want_rows "")
foreach(scene_bodies compounds:3000 junkyard:8000 rain:11000 spinner:6077 tumbler:2026 washer:8100)
  string(REPLACE ":" ";" pair "${scene_bodies}")
  list(GET pair 0 scene)
  list(GET pair 1 bodies)
  list(APPEND want_rows "${scene}:physim:1:${bodies}")
  if(PEER AND NOT scene MATCHES "^(junkyard|spinner|washer)$")
    string(REPLACE ":1" "" peer_name "${PEER}")
    list(APPEND want_rows "${scene}:${peer_name}:1:${bodies}")
  endif()
endforeach()
set(got_rows "")
string(JSON rows LENGTH "${bench_json}")
math(EXPR last "${rows} - 1")
foreach(i RANGE ${last})
  string(JSON scene GET "${bench_json}" ${i} scene)
  string(JSON engine GET "${bench_json}" ${i} engine)
  string(JSON threads GET "${bench_json}" ${i} threads)
  string(JSON bodies GET "${bench_json}" ${i} bodies)
  if(threads EQUAL 1)
    list(APPEND got_rows "${scene}:${engine}:1:${bodies}")
  endif()
  if(scene STREQUAL "tumbler")
    bench_smoke_number("${bench_json}" lowest ${i} lowest_y)
    if(NOT lowest GREATER -3.42)
      message(FATAL_ERROR "${engine} x${threads}: a box of tumbler at ${lowest} m, out of its drum")
    endif()
  endif()
endforeach()
if(NOT got_rows STREQUAL want_rows)
  message(FATAL_ERROR "one-thread rows ${got_rows}, expected ${want_rows}")
endif()
if(PEER AND NOT bench_stdout MATCHES "does not run junkyard: .*does not run spinner: .*does not run washer: ")
  message(FATAL_ERROR "no note on the scenes Box2D 2.4.1 does not run:\n${bench_stdout}")
endif()

bench_smoke_usage_errors("${PEER_BENCH}" "--repeats 0" "--scenes no_such_scene" "--steps 100" "--frobnicate"
  "--substeps 0" "--substeps 4,x" "--substeps 1001")
file(REMOVE_RECURSE "${WORK_DIR}")
