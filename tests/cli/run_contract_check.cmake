# Runs ../shared/tools/check_cli_contract.py; exits 77 (skipped) when ../shared is absent.
if(NOT EXISTS "${CHECKER}")
  message("SKIPPED: ${CHECKER} not found (../shared is not beside the checkout)")
  cmake_language(EXIT 77)
endif()
execute_process(COMMAND "${PYTHON}" "${CHECKER}" "${BINARY}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "check_cli_contract.py failed (exit ${rc})")
endif()
