# End-to-end checks of the morphogen command: exit codes, one-line errors that
# name the problem, no half-written files, and a session JSON that reproduces
# its image. Run by ctest: cmake -DMORPHOGEN=... -DWORK=... -DSOURCE=... -P cli_test.cmake

file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
set(failures 0)

# run(<expected exit code> <text stderr must contain or ""> args...)
function(run expected needle)
  execute_process(COMMAND ${MORPHOGEN} ${ARGN}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err WORKING_DIRECTORY "${WORK}")
  set(ok TRUE)
  if(NOT rc EQUAL expected)
    set(ok FALSE)
  endif()
  if(NOT needle STREQUAL "")
    string(FIND "${err}" "${needle}" at)
    if(at EQUAL -1)
      set(ok FALSE)
    endif()
  endif()
  if(ok)
    message(STATUS "ok: morphogen ${ARGN}")
  else()
    message(SEND_ERROR "FAILED: morphogen ${ARGN}\n  want exit ${expected} and stderr containing '${needle}'\n  got exit ${rc}\n  stderr: ${err}")
  endif()
  set(last_stdout "${out}" PARENT_SCOPE)
endfunction()

run(0 "" --help)
run(0 "" render --help)
run(0 "" presets)
string(FIND "${last_stdout}" "gs_coral" at)
if(at EQUAL -1)
  message(SEND_ERROR "presets does not list gs_coral: ${last_stdout}")
endif()

# Bad input: exit 2 with a message naming the problem.
run(2 "unknown preset 'nope'" render --preset nope --out a.png)
run(2 "unsupported image extension '.jpg'" render --preset gs_coral --size 16 --steps 1 --out a.jpg)
run(2 "does not exist" render --preset gs_coral --size 16 --steps 1 --out missing/a.png)
run(2 "is not a parameter of gray_scott" render --preset gs_coral --param Q=1 --out a.png)
run(2 "--size 'big'" render --preset gs_coral --size big --out a.png)
run(2 "--backend 'fpga'" render --preset gs_coral --size 16 --steps 1 --backend fpga --out a.png)
run(2 "--context 'dx12'" render --preset gs_coral --size 16 --steps 1 --backend gpu --context dx12 --out a.png)
run(2 "colour map 'rainbow'" render --preset gs_coral --size 16 --steps 1 --colormap rainbow --out a.png)
run(2 "--preset and --session are exclusive" render --preset gs_coral --session x.json --out a.png)
run(2 "" render --preset gs_coral --no-such-flag)
file(WRITE "${WORK}/broken.json" "{\"model\": \"gray_scott\", \"params\": {\"F\": \"x\"}}")
run(2 "broken.json: field 'params.F' must be a number" render --session broken.json --out a.png)
file(WRITE "${WORK}/truncated.json" "{\"model\": ")
run(2 "truncated.json: not valid JSON" render --session truncated.json --out a.png)
run(2 "cannot open session file" render --session none.json --out a.png)
if(EXISTS "${WORK}/a.png")
  message(SEND_ERROR "a failed render left a.png behind")
endif()

# A blow-up stops with the step and a dt to try, and writes no image.
run(1 "try a smaller time step such as --dt" render --preset mcgraw_turing --size 32 --steps 1000 --dt 0.031 --backend cpu --out blown.png)
if(EXISTS "${WORK}/blown.png")
  message(SEND_ERROR "a blown-up run wrote an image")
endif()

# A dt beyond the explicit limit from the operator's symbol is capped, and says so.
run(0 "exceeds the explicit stability limit 1.192" render --preset gs_coral --size 16 --steps 20 --dt 5 --backend cpu --out capped.png)
file(READ "${WORK}/capped.json" capped)
string(FIND "${capped}" "\"dt\": 1.07" at)
if(at EQUAL -1)
  message(SEND_ERROR "the capped dt is not what the session records: ${capped}")
endif()
# An operator that grows for every dt is refused.
file(WRITE "${WORK}/unstable.json" "{\"model\": \"gray_scott\", \"size\": 16, \"steps\": 5,
  \"diffusion\": {\"type\": \"generalized\", \"tensors\": {\"u\": \"d\", \"v\": \"d\"}, \"stabilize\": false}}")
run(2 "grow for every explicit time step" render --session unstable.json --backend cpu --out unstable.png)

# A real render on each backend, then the written session reproduces it exactly.
foreach(backend cpu gpu)
  run(0 "${backend} backend" render --preset turk_small_spots --size 32 --steps 200 --backend ${backend} --context osmesa --out ${backend}.png)
  if(NOT EXISTS "${WORK}/${backend}.png" OR NOT EXISTS "${WORK}/${backend}.json")
    message(SEND_ERROR "render --backend ${backend} did not write the image and its session")
  endif()
  run(0 "" render --session ${backend}.json --backend ${backend} --context osmesa --out ${backend}_again.png)
  file(SHA256 "${WORK}/${backend}.png" first)
  file(SHA256 "${WORK}/${backend}_again.png" second)
  if(NOT first STREQUAL second)
    message(SEND_ERROR "the session written with ${backend}.png does not reproduce it")
  endif()
endforeach()

# Every output format.
run(0 "" render --preset gs_coral --size 24 --steps 10 --backend cpu --bit-depth 16 --out deep.png)
run(0 "" render --preset gs_coral --size 24 --steps 10 --backend cpu --out raw.exr)
run(0 "" render --preset gs_coral --size 24 --steps 10 --backend cpu --out flat.tif --session-out flat_session.json)
foreach(f deep.png raw.exr flat.tif flat_session.json)
  if(NOT EXISTS "${WORK}/${f}")
    message(SEND_ERROR "expected ${f}")
  endif()
endforeach()
