# bench's memory rows end to end: each render runs in its own process and
# reports its peak memory; the row's growth above a 16x16 render, over the
# state it simulates, must be near what the render holds (two state buffers on
# the CPU: about 2), not 0 (a peak that is the bench's own, as wait4's
# ru_maxrss would give) and not a copy too many.
# Run by ctest: cmake -DMORPHOGEN=... -DWORK=... -P cli_bench_test.cmake

file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

execute_process(COMMAND ${MORPHOGEN} bench --memory-sizes 3
  RESULT_VARIABLE rc ERROR_VARIABLE err WORKING_DIRECTORY "${WORK}")
string(FIND "${err}" "--memory-sizes '3': '3' is not a size" at)
if(NOT rc EQUAL 2 OR at EQUAL -1)
  message(SEND_ERROR "bench --memory-sizes 3: want exit 2 naming the flag, got exit ${rc}: ${err}")
endif()

# The other rows at their smallest: throughput at 16x16, no domains or convergence.
execute_process(COMMAND ${MORPHOGEN} bench --sizes 16 --operator-sizes 16 --seconds 0.01
  --no-domains --no-surface --no-convergence --no-resolution --no-designer --memory-sizes 1024 --json bench.json
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err WORKING_DIRECTORY "${WORK}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "bench with memory rows: exit ${rc}\n${err}")
endif()
string(FIND "${out}" "growth/state" at)
if(at EQUAL -1)
  message(SEND_ERROR "bench prints no memory table:\n${out}")
endif()

file(READ "${WORK}/bench.json" report)
string(JSON rows ERROR_VARIABLE json_error LENGTH "${report}" memory)
if(json_error OR rows LESS 1)
  message(FATAL_ERROR "bench.json has no memory rows: ${json_error}")
endif()
set(cpu_rows 0)
math(EXPR last "${rows} - 1")
foreach(i RANGE ${last})
  string(JSON backend GET "${report}" memory ${i} backend)
  string(JSON size GET "${report}" memory ${i} size)
  string(JSON state GET "${report}" memory ${i} state_mb)
  string(JSON peak ERROR_VARIABLE row_error GET "${report}" memory ${i} peak_rss_mb)
  string(JSON growth ERROR_VARIABLE row_error GET "${report}" memory ${i} growth_over_state)
  if(row_error)
    string(JSON why ERROR_VARIABLE none GET "${report}" memory ${i} error)
    message(SEND_ERROR "memory row ${i} (${backend} ${size}) has no figures: ${why}")
    continue()
  endif()
  # 1024 x 1024 x 2 chemicals x 4 bytes
  if(NOT size EQUAL 1024 OR NOT state GREATER 8.38 OR NOT state LESS 8.39)
    message(SEND_ERROR "memory row ${i}: size ${size}, state ${state} MB (want 1024, 8.39 MB)")
  endif()
  if(backend STREQUAL "cpu")
    math(EXPR cpu_rows "${cpu_rows} + 1")
    if(NOT growth GREATER 0.5 OR NOT growth LESS 4)
      message(SEND_ERROR "cpu render at 1024: peak ${peak} MB, growth over the state ${growth} (want 0.5 to 4)")
    else()
      message(STATUS "ok: cpu render at 1024: peak ${peak} MB, growth over the state ${growth}")
    endif()
  elseif(NOT growth GREATER 0.5 OR NOT growth LESS 10)
    # The GPU driver's own memory counts too (llvmpipe keeps textures in ours).
    message(SEND_ERROR "${backend} render at 1024: peak ${peak} MB, growth over the state ${growth} (want 0.5 to 10)")
  else()
    message(STATUS "ok: ${backend} render at 1024: peak ${peak} MB, growth over the state ${growth}")
  endif()
endforeach()
if(NOT cpu_rows EQUAL 1)
  message(SEND_ERROR "want one cpu memory row, got ${cpu_rows}")
endif()

# The surface rows alone (issue 11): mesh to atlas for the 81,920-triangle blob
# with its phase times, the holes atlas's throughput against a grid and its
# kernels against a probe, and a session step's cost on three models, each
# with finite positive figures.
execute_process(COMMAND ${MORPHOGEN} bench --seconds 0.01 --no-throughput --no-domains
  --no-convergence --no-memory --no-resolution --no-designer --json surface.json
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err WORKING_DIRECTORY "${WORK}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "bench surface rows: exit ${rc}\n${err}")
endif()
file(READ "${WORK}/surface.json" report)
string(JSON triangles GET "${report}" surface mesh_to_atlas triangles)
string(JSON texels GET "${report}" surface mesh_to_atlas texels)
string(JSON seconds GET "${report}" surface mesh_to_atlas seconds)
string(JSON projection GET "${report}" surface mesh_to_atlas phases projection)
if(NOT triangles EQUAL 81920 OR NOT texels GREATER 1000 OR NOT seconds GREATER 0
   OR NOT projection GREATER 0 OR projection GREATER seconds)
  message(SEND_ERROR "mesh to atlas: ${triangles} triangles, ${texels} texels, ${seconds} s, projection ${projection} s")
endif()
string(JSON rows LENGTH "${report}" surface throughput)
if(rows LESS 2)
  message(SEND_ERROR "want throughput rows at two tile sizes, got ${rows}")
endif()
math(EXPR last "${rows} - 1")
foreach(i RANGE ${last})
  string(JSON fraction GET "${report}" surface throughput ${i} fraction_of_grid)
  string(JSON substeps GET "${report}" surface throughput ${i} substeps)
  if(NOT fraction GREATER 0 OR substeps LESS 1)
    message(SEND_ERROR "surface throughput row ${i}: fraction ${fraction}, substeps ${substeps}")
  endif()
endforeach()
# The CPU atlas kernels against a probe of their memory traffic: the explicit
# step and a relaxation pass at both tile sizes (the fraction is a
# measurement, checked only to be a finite positive figure).
string(JSON rows LENGTH "${report}" surface kernel_probe)
if(NOT rows EQUAL 4)
  message(SEND_ERROR "want kernel probe rows for two kernels at two tile sizes, got ${rows}")
endif()
foreach(i RANGE 3)
  string(JSON fraction GET "${report}" surface kernel_probe ${i} fraction_of_probe)
  if(NOT fraction GREATER 0)
    message(SEND_ERROR "surface kernel_probe row ${i}: fraction ${fraction}")
  endif()
endforeach()
# A session step's cost on three models, both integrators and a flat grid,
# per backend (whichever is faster is a measurement, not checked here).
string(JSON rows LENGTH "${report}" surface session_step)
math(EXPR per_backend "${rows} % 3")
if(rows LESS 3 OR NOT per_backend EQUAL 0)
  message(SEND_ERROR "want session-step rows for three models per backend, got ${rows}")
endif()
math(EXPR last "${rows} - 1")
foreach(i RANGE ${last})
  foreach(key explicit_seconds_per_step semi_implicit_seconds_per_step grid_seconds_per_step
              best_over_grid semi_implicit_speedup)
    string(JSON value GET "${report}" surface session_step ${i} ${key})
    if(NOT value GREATER 0)
      message(SEND_ERROR "surface session_step row ${i}: ${key} is ${value}")
    endif()
  endforeach()
  string(JSON substeps GET "${report}" surface session_step ${i} explicit_substeps)
  if(substeps LESS 2)
    message(SEND_ERROR "surface session_step row ${i}: ${substeps} explicit substeps (the models' texels need several)")
  endif()
endforeach()
