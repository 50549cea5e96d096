# Runs the halfwing tool once and checks its exit code and output: a CTest step for the CLI.
# -DCLI=path -DARGS="a|b|c" -DEXPECT_CODE=n [-DEXPECT_STDOUT=regex] [-DEXPECT_STDERR=regex]
# [-DEXPECT_FILE=path] (a file the run must create, removed first).

if(DEFINED EXPECT_FILE)
  file(REMOVE "${EXPECT_FILE}")
endif()
string(REPLACE "|" ";" ARGS "${ARGS}")
execute_process(COMMAND "${CLI}" ${ARGS}
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(what "halfwing ${ARGS}\n--- stdout:\n${out}\n--- stderr:\n${err}")
if(NOT code STREQUAL "${EXPECT_CODE}")
  message(FATAL_ERROR "exit code ${code}, expected ${EXPECT_CODE}: ${what}")
endif()
if(DEFINED EXPECT_STDOUT AND NOT out MATCHES "${EXPECT_STDOUT}")
  message(FATAL_ERROR "stdout does not match '${EXPECT_STDOUT}': ${what}")
endif()
if(DEFINED EXPECT_STDERR AND NOT err MATCHES "${EXPECT_STDERR}")
  message(FATAL_ERROR "stderr does not match '${EXPECT_STDERR}': ${what}")
endif()
if(DEFINED EXPECT_FILE AND NOT EXISTS "${EXPECT_FILE}")
  message(FATAL_ERROR "${EXPECT_FILE} was not written: ${what}")
endif()
