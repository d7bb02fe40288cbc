# Runs ../shared/tools/check_cli_contract.py; reports itself skipped ("SKIPPED:", matched by
# the test's SKIP_REGULAR_EXPRESSION) when ../shared is absent. cmake_language(EXIT) would
# need CMake 3.29; Debian 12 has 3.25.
if(NOT EXISTS "${CHECKER}")
  message("SKIPPED: ${CHECKER} not found (../shared is not beside the checkout)")
  return()
endif()
execute_process(COMMAND "${PYTHON}" "${CHECKER}" "${BINARY}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "check_cli_contract.py failed (exit ${rc})")
endif()
