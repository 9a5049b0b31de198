# Runs run_golden.cmake and passes only if it fails with EXPECTED_MESSAGE in its output.
execute_process(COMMAND "${CMAKE_COMMAND}" -DGOLDEN_CONFIG=${GOLDEN_CONFIG} -P "${RUNNER}"
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
message("${output}")
if(result EQUAL 0)
  message(FATAL_ERROR "the golden runner passed; it must fail here")
endif()
if(NOT output MATCHES "${EXPECTED_MESSAGE}")
  message(FATAL_ERROR "the golden runner failed, but without saying '${EXPECTED_MESSAGE}'")
endif()
