# render --frames / --every / --video end to end: frames from one run, bad flags,
# and the message (exit 0, frames kept) when ffmpeg is not installed.
# Run by ctest: cmake -DMORPHOGEN=... -DWORK=... -P cli_frames_test.cmake

file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/nopath" "${WORK}/fakebin")
set(small render --preset gs_coral --size 24 --steps 60 --backend cpu)

# run(<expected exit code> <text stderr must contain or ""> args...), with PATH
# set to ${path} (a folder without ffmpeg unless the test puts one there).
function(run expected needle path)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env PATH=${path} ${MORPHOGEN} ${ARGN}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err WORKING_DIRECTORY "${WORK}")
  string(FIND "${err}" "${needle}" at)
  if(NOT rc EQUAL expected OR (NOT needle STREQUAL "" AND at EQUAL -1))
    message(SEND_ERROR "FAILED: morphogen ${ARGN}\n  want exit ${expected} and stderr containing '${needle}'\n  got exit ${rc}\n  stderr: ${err}")
  else()
    message(STATUS "ok: morphogen ${ARGN}")
  endif()
  set(last_stderr "${err}" PARENT_SCOPE)
endfunction()

function(expect_same a b)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${WORK}/${a}" "${WORK}/${b}"
    RESULT_VARIABLE differ)
  if(differ)
    message(SEND_ERROR "${a} and ${b} differ (or one is missing)")
  endif()
endfunction()

set(nopath "${WORK}/nopath")

# Bad flags: exit 2, named.
run(2 "--frames 0: accepted are 1 or more" ${nopath} ${small} --frames 0 --out a.png)
run(2 "--frames and --every are exclusive" ${nopath} ${small} --frames 3 --every 10 --out a.png)
run(2 "unsupported extension '.avi'" ${nopath} ${small} --frames 3 --video x.avi --out a.png)
run(2 "--every -5" ${nopath} ${small} --every -5 --out a.png)
run(2 "--video needs --frames N or --every K" ${nopath} ${small} --video x.mp4 --out a.png)
run(2 "--frame-range '3:1'" ${nopath} ${small} --frames 3 --frame-range 3:1 --out a.png)
run(2 "--fps" ${nopath} ${small} --frames 3 --fps 0 --out a.png)
if(EXISTS "${WORK}/a_frames/frame_00000.png" OR EXISTS "${WORK}/a.png")
  message(SEND_ERROR "a refused render wrote frames or an image")
endif()

# --frames 3: three frames next to --out; --every 20 takes the same steps (20, 40, 60) of
# the same run, so the same files; the last is the final state, the lone frame of --frames 1.
run(0 "3 frames into a_frames" ${nopath} ${small} --frames 3 --out a.png)
foreach(i 0 1 2)
  if(NOT EXISTS "${WORK}/a_frames/frame_0000${i}.png")
    message(SEND_ERROR "--frames 3 did not write a_frames/frame_0000${i}.png")
  endif()
endforeach()
if(EXISTS "${WORK}/a_frames/frame_00003.png" OR NOT EXISTS "${WORK}/a.png")
  message(SEND_ERROR "--frames 3 wrote a fourth frame, or no --out image")
endif()
# A cascade whose colour map names a chemical of its last stage only
# (turk_giraffe's g2): the frames of its first stage show that stage's own
# display chemical, and every frame is written.
run(0 "4 frames into giraffe_frames" ${nopath} render --preset turk_giraffe --size 32 --backend cpu
    --frames 4 --out giraffe.png)
foreach(i 0 1 2 3)
  if(NOT EXISTS "${WORK}/giraffe_frames/frame_0000${i}.png")
    message(SEND_ERROR "turk_giraffe --frames 4 did not write giraffe_frames/frame_0000${i}.png")
  endif()
endforeach()
run(0 "" ${nopath} ${small} --every 20 --out b.png --frames-dir every)
foreach(i 0 1 2)
  expect_same(a_frames/frame_0000${i}.png every/frame_0000${i}.png)
endforeach()
run(0 "" ${nopath} ${small} --frames 1 --out c.png)
expect_same(a_frames/frame_00002.png c_frames/frame_00000.png)
# The frames are the run's states in the locked levels, not the --out image's min-max.
run(0 "" ${nopath} ${small} --frames 1 --out d.png --frames-dir d_frames --frame-range 0:0.25)
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${WORK}/c_frames/frame_00000.png"
  "${WORK}/d_frames/frame_00000.png" RESULT_VARIABLE differ)
if(NOT differ)
  message(SEND_ERROR "--frame-range 0:0.25 gave the same frame as the display range 0:0.5")
endif()
# A rerun with fewer frames leaves none of the old ones behind.
run(0 "" ${nopath} ${small} --frames 2 --out a.png)
if(EXISTS "${WORK}/a_frames/frame_00002.png")
  message(SEND_ERROR "a rerun with --frames 2 left frame_00002.png of the earlier run")
endif()

# Without ffmpeg: exit 0, the frames written, and the exact command to run.
run(0 "ffmpeg not found: frames are in v_frames; install it (apt-get install ffmpeg) and run:"
    ${nopath} ${small} --frames 3 --out v.png --video v.mp4 --fps 12)
string(FIND "${last_stderr}" "ffmpeg -y -loglevel error -framerate 12 -i 'v_frames/frame_%05d.png'" at)
if(at EQUAL -1 OR NOT EXISTS "${WORK}/v_frames/frame_00002.png")
  message(SEND_ERROR "no-ffmpeg message lacks the command or frames are missing: ${last_stderr}")
endif()

# With an ffmpeg on PATH (a stand-in that records its arguments and writes the video).
file(WRITE "${WORK}/fakebin/ffmpeg" "#!/bin/sh\necho \"$@\" > ffmpeg_args.txt\nfor a; do last=$a; done\necho video > \"$last\"\n")
file(CHMOD "${WORK}/fakebin/ffmpeg" PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
run(0 "" "${WORK}/fakebin" ${small} --every 30 --out g.png --video g.gif)
if(NOT EXISTS "${WORK}/g.gif" OR NOT EXISTS "${WORK}/ffmpeg_args.txt")
  message(SEND_ERROR "--video with ffmpeg on PATH did not run it")
else()
  file(READ "${WORK}/ffmpeg_args.txt" args)
  string(FIND "${args}" "palettegen" at)
  if(at EQUAL -1)
    message(SEND_ERROR "gif encoding without a palette pass: ${args}")
  endif()
endif()
