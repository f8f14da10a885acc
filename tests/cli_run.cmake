# The run() helper of the CLI tests (include()d): runs morphogen in ${WORK} and
# checks its exit code and a text on stderr; last_stdout and last_stderr keep
# the output for further checks.

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
  set(last_stderr "${err}" PARENT_SCOPE)
endfunction()
