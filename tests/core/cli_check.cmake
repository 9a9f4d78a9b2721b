# Runs one `sextant` command and checks its exit code and output:
# cmake -DCOMMAND="exe;arg;…" -DEXPECT_EXIT=0 -DEXPECT_REGEX="…" [-DSETUP_DIR=…] [-DTOUCH=file] -P cli_check.cmake
if(TOUCH)  # an empty file to feed the command
  file(WRITE "${TOUCH}" "")
endif()
if(SETUP_DIR)
  file(REMOVE_RECURSE "${SETUP_DIR}")
  file(MAKE_DIRECTORY "${SETUP_DIR}")
endif()
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(all "${out}${err}")
if(NOT result EQUAL EXPECT_EXIT)
  message(FATAL_ERROR "exit code ${result}, expected ${EXPECT_EXIT}\n${all}")
endif()
if(NOT all MATCHES "${EXPECT_REGEX}")
  message(FATAL_ERROR "output does not match '${EXPECT_REGEX}':\n${all}")
endif()
message(STATUS "${all}")
