# Preprocesses each header a game may include, alone, with the engine's include flags, and fails
# if Vulkan's vulkan_core.h (or GLM, the renderer's math library) is pulled in. Run by ctest
# (runtime.game_headers_without_vulkan):
#   cmake -DCOMPILER=... -DINCLUDES="dir|dir|..." -DSOURCE_DIR=... -P check_game_headers.cmake
# The headers are every header under runtime/include, ecs/include and content/include except
# the engine-side ones below, which tools built into the engine (the `candela` executable, the
# editor) use to reach the renderer and which games do not need.
set(ENGINE_SIDE
  runtime/include/candela/runtime/atmosphere_sun.h      # the atmosphere's sun (render lights)
  runtime/include/candela/runtime/frame_extraction.h    # ECS -> render arrays (render types)
  runtime/include/candela/runtime/layer_pass_context.h  # what a FrameLayer records with (Vulkan)
  runtime/include/candela/runtime/light_table.h         # render light slots
  runtime/include/candela/runtime/scene_source.h        # `candela run`/editor scene loading
  runtime/include/candela/runtime/sky_loader.h          # GPU sky loading
)
string(REPLACE "|" ";" include_list "${INCLUDES}")
set(flags)
foreach(dir IN LISTS include_list)
  if(dir)
    list(APPEND flags "-I${dir}")
  endif()
endforeach()
file(GLOB_RECURSE headers RELATIVE "${SOURCE_DIR}"
     "${SOURCE_DIR}/runtime/include/*.h" "${SOURCE_DIR}/ecs/include/*.h"
     "${SOURCE_DIR}/content/include/*.h")
list(REMOVE_ITEM headers ${ENGINE_SIDE})
list(SORT headers)
list(LENGTH headers count)
if(count LESS 20)
  message(FATAL_ERROR "only ${count} game headers found under ${SOURCE_DIR}: wrong SOURCE_DIR?")
endif()
set(failed)
foreach(header IN LISTS headers)
  execute_process(
    COMMAND "${COMPILER}" -std=c++20 -E -x c++ ${flags} "${SOURCE_DIR}/${header}"
    OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    list(APPEND failed "${header}: does not preprocess alone: ${err}")
  elseif(out MATCHES "vulkan_core\\.h")
    list(APPEND failed "${header}: includes vulkan_core.h")
  elseif(out MATCHES "/glm/")
    list(APPEND failed "${header}: includes GLM (render math, games use ecs/transform_math.h)")
  endif()
endforeach()
if(failed)
  list(JOIN failed "\n  " text)
  message(FATAL_ERROR "game headers that need Vulkan or GLM (or do not stand alone):\n  ${text}")
endif()
message(STATUS "${count} game headers preprocess without vulkan_core.h and GLM")
