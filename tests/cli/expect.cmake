# Run a command and check its exit code and output (stdout + stderr):
#   cmake -DCMD="soma;study;run;x" -DRC=2 -DMATCH="regex" -P expect.cmake
# Used by CTest to test the `soma` command line's contract (DESIGN §6, §10).
# STDOUT=FILE: the command's stdout goes to FILE (e.g. /dev/full) and only stderr is matched.
if(DEFINED STDOUT AND NOT "${STDOUT}" STREQUAL "")
  execute_process(COMMAND ${CMD} RESULT_VARIABLE rc OUTPUT_FILE "${STDOUT}" ERROR_VARIABLE err TIMEOUT 600)
  set(out "")
else()
  execute_process(COMMAND ${CMD} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err
                  TIMEOUT 600)
endif()
set(all "${out}${err}")
# SOMA_CLI_SNAPSHOT=DIR: also keep each command's exit code and output in DIR/<test name>.txt, so
# that two builds' CLI outputs can be compared byte for byte (scripts/cli_snapshot.sh).
if(DEFINED ENV{SOMA_CLI_SNAPSHOT} AND DEFINED NAME)
  string(MAKE_C_IDENTIFIER "${NAME}" file)
  file(WRITE "$ENV{SOMA_CLI_SNAPSHOT}/${file}.txt" "exit ${rc}\n--- stdout ---\n${out}--- stderr ---\n${err}")
endif()
if(NOT "${rc}" STREQUAL "${RC}")
  message(FATAL_ERROR "expected exit code ${RC}, got ${rc}\n--- output ---\n${all}")
endif()
if(DEFINED MATCH AND NOT "${all}" MATCHES "${MATCH}")
  message(FATAL_ERROR "output does not match '${MATCH}'\n--- output ---\n${all}")
endif()
# NOMATCH: a regex the output must not match (e.g. a node that must not be built).
if(DEFINED NOMATCH AND NOT "${NOMATCH}" STREQUAL "" AND "${all}" MATCHES "${NOMATCH}")
  message(FATAL_ERROR "output matches '${NOMATCH}', which it must not\n--- output ---\n${all}")
endif()
message(STATUS "exit ${rc} as expected")
