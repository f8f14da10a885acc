# cmake --install of a build into a fresh prefix: the command, its bash
# completion and its man page land where Debian looks for them, and the
# installed command runs.
# Run by ctest: cmake -DBUILD=... -DWORK=... -P install_test.cmake

file(REMOVE_RECURSE "${WORK}")
execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD}" --prefix "${WORK}/prefix"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install: exit ${rc}\n${out}${err}")
endif()
foreach(file bin/morphogen share/bash-completion/completions/morphogen share/man/man1/morphogen.1)
  if(NOT EXISTS "${WORK}/prefix/${file}")
    message(SEND_ERROR "not installed: ${file}")
  endif()
endforeach()
execute_process(COMMAND "${WORK}/prefix/bin/morphogen" --version
  RESULT_VARIABLE rc OUTPUT_VARIABLE version)
if(NOT rc EQUAL 0 OR NOT version MATCHES "^morphogen [0-9]")
  message(SEND_ERROR "the installed morphogen --version: exit ${rc}, '${version}'")
endif()
file(READ "${WORK}/prefix/share/man/man1/morphogen.1" man)
file(READ "${WORK}/prefix/share/bash-completion/completions/morphogen" completion)
foreach(needle ".TH MORPHOGEN" "render" "presets" "design")
  string(FIND "${man}" "${needle}" at)
  if(at EQUAL -1)
    message(SEND_ERROR "the man page lacks '${needle}'")
  endif()
endforeach()
string(FIND "${completion}" "complete -o default -F _morphogen morphogen" at)
if(at EQUAL -1)
  message(SEND_ERROR "the installed completion does not register _morphogen")
endif()
