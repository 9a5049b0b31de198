# Runs one golden test: renders its scene with the engine, then compares both captures with
# the stored images using candela-golden. Any engine failure fails the test: a non-zero exit,
# 3 (validation messages while CANDELA_VALIDATION=require) included, and errors loading the
# scene.
#
#   cmake -DGOLDEN_CONFIG=<build>/golden/<name>/golden.cmake [-DMODE=test|render|store]
#         -P run_golden.cmake
#
# MODE test (default) renders and compares. scripts/update-goldens uses `render` (render, and
# refuse an image with NaN/Inf) for every name first and `store` (copy the captures into the
# expected directory) only once all rendered, so a failure part way changes no golden.
cmake_minimum_required(VERSION 3.25)
include("${GOLDEN_CONFIG}")
if(NOT MODE)
  set(MODE test)
endif()
set(exr "${GOLDEN_OUTPUT_DIR}/${GOLDEN_NAME}.exr")
set(png "${GOLDEN_OUTPUT_DIR}/${GOLDEN_NAME}.png")
set(stats "${GOLDEN_OUTPUT_DIR}/${GOLDEN_NAME}.stats.json")
if(NOT DEFINED ENV{CANDELA_VALIDATION})
  set(ENV{CANDELA_VALIDATION} require)
endif()

if(MODE STREQUAL "store")
  foreach(capture "${exr}" "${png}")
    if(NOT EXISTS "${capture}")
      message(FATAL_ERROR "golden ${GOLDEN_NAME}: ${capture} was not rendered")
    endif()
  endforeach()
  file(MAKE_DIRECTORY "${GOLDEN_EXPECTED_DIR}")
  file(COPY_FILE "${exr}" "${GOLDEN_EXPECTED_DIR}/${GOLDEN_NAME}.exr")
  file(COPY_FILE "${png}" "${GOLDEN_EXPECTED_DIR}/${GOLDEN_NAME}.png")
  message(STATUS "stored ${GOLDEN_EXPECTED_DIR}/${GOLDEN_NAME}.exr and .png")
  return()
endif()

foreach(executable "${GOLDEN_ENGINE}" "${GOLDEN_TOOL}")
  if(NOT EXISTS "${executable}")
    message(FATAL_ERROR "golden ${GOLDEN_NAME}: ${executable} is not built; build the tree "
                        "first (scripts/build build)")
  endif()
endforeach()
# A capture left from an earlier run must never stand in for this one.
file(REMOVE "${exr}" "${png}" "${stats}")
file(MAKE_DIRECTORY "${GOLDEN_OUTPUT_DIR}")

# Pinned: antialiasing and bloom off (the application's defaults are TAA, whose jitter and
# history make the image depend on the frame count, and a little bloom), so these images keep
# testing one unfiltered sample per pixel of the scene's radiance.
if(NOT GOLDEN_AA)
  set(GOLDEN_AA off)
endif()
if(GOLDEN_BLOOM STREQUAL "")
  set(GOLDEN_BLOOM 0)
endif()
# The ultra preset (the engine's settings before presets: its goldens hold that image; a
# device's default preset would otherwise change them with the machine).
# Screen-space reflections off (the application's default, hiz, would change every golden
# with a glossy surface; an entry that checks them asks with "args": "--ssr hiz", which comes
# later and wins). And the camera's manual exposure, not the metered one. GOLDEN_ARGS: the
# entry's own flags.
separate_arguments(golden_args UNIX_COMMAND "${GOLDEN_ARGS}")
# A preset golden holds what a user sees at that preset: its own antialiasing, bloom and
# reflections (only the exposure stays the camera's).
set(pinned --quality ultra --aa "${GOLDEN_AA}" --bloom "${GOLDEN_BLOOM}" --ssr off)
if(GOLDEN_PRESET)
  set(pinned --quality "${GOLDEN_PRESET}")
endif()
execute_process(
  COMMAND "${GOLDEN_ENGINE}" run "${GOLDEN_SCENE}" --headless --size "${GOLDEN_SIZE}"
          --frames "${GOLDEN_FRAMES}" --capture "${exr}" --capture "${png}" --stats "${stats}"
          ${pinned} --exposure manual ${golden_args}
  RESULT_VARIABLE engine_result OUTPUT_VARIABLE engine_output ERROR_VARIABLE engine_output)
message("${engine_output}")
if(engine_result EQUAL 3)
  message(FATAL_ERROR "golden ${GOLDEN_NAME}: FAIL: the engine reported Vulkan validation "
                      "messages (exit 3); a golden must render without any")
elseif(NOT engine_result EQUAL 0)
  message(FATAL_ERROR "golden ${GOLDEN_NAME}: FAIL: `${GOLDEN_ENGINE} run ${GOLDEN_SCENE}` "
                      "failed (exit ${engine_result})")
endif()
# The engine renders what it could load and reports the rest as "<file>: error: ..." lines;
# a golden of a scene with missing content would guard nothing.
if(engine_output MATCHES "(^|\n)candela: [^\n]*: error: ")
  message(FATAL_ERROR "golden ${GOLDEN_NAME}: FAIL: the engine reported errors while loading "
                      "${GOLDEN_SCENE} (above); a golden must load its whole scene")
endif()

if(MODE STREQUAL "render")
  execute_process(COMMAND "${GOLDEN_TOOL}" inspect "${exr}" RESULT_VARIABLE inspect_result)
  if(NOT inspect_result EQUAL 0)
    message(FATAL_ERROR "golden ${GOLDEN_NAME}: refusing to store a capture with NaN/Inf "
                        "or that cannot be read")
  endif()
  return()
endif()

execute_process(
  COMMAND "${GOLDEN_TOOL}" check "${GOLDEN_NAME}" --actual-dir "${GOLDEN_OUTPUT_DIR}"
          --expected-dir "${GOLDEN_EXPECTED_DIR}"
  RESULT_VARIABLE check_result)
if(NOT check_result EQUAL 0)
  # The device drew it: a driver or lane width other than the goldens' is the first suspect.
  file(READ "${stats}" stats_text)
  string(JSON device ERROR_VARIABLE device_error GET "${stats_text}" device)
  if(device_error)
    set(device "an unknown device")
  endif()
  message(FATAL_ERROR "golden ${GOLDEN_NAME}: FAIL (candela-golden exit ${check_result}), "
                      "rendered on ${device}; goldens are recorded on lavapipe at 256 bits")
endif()
