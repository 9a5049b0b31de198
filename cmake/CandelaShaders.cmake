# Compiles GLSL to SPIR-V at build time and embeds it as a C++ header
# (`<name>_spv` uint32_t array). Build-time compilation keeps glslang out of the runtime and
# turns shader errors into build errors; specialization constants give the per-scene variants.
find_program(GLSLANG_VALIDATOR glslangValidator REQUIRED)

function(candela_add_shaders target)
  cmake_parse_arguments(ARG "" "" "SHADERS;INCLUDE_DIRS" ${ARGN})
  set(out_dir ${CMAKE_CURRENT_BINARY_DIR}/generated/shaders)
  file(MAKE_DIRECTORY ${out_dir})
  set(include_flags)
  foreach(dir ${ARG_INCLUDE_DIRS})
    list(APPEND include_flags -I${dir})
    # .h: headers shared with C++ (common/specialization_ids.h, common/shared_bindings.h).
    file(GLOB_RECURSE glsl_headers ${dir}/*.glsl ${dir}/*.h)
    list(APPEND shared_glsl ${glsl_headers})
  endforeach()
  set(headers)
  foreach(shader ${ARG_SHADERS})
    get_filename_component(abs ${shader} ABSOLUTE)
    # Binding numbers of the shader's pass, shared with its C++ (<pass>_bindings.h beside it).
    get_filename_component(shader_dir ${abs} DIRECTORY)
    # and any GLSL the pass's shaders share (gbuffer_fragment.glsl: one body, two variants).
    file(GLOB pass_headers ${shader_dir}/*_bindings.h ${shader_dir}/*.glsl)
    get_filename_component(file_name ${shader} NAME)
    string(REPLACE "." "_" var_name ${file_name})
    set(header ${out_dir}/${file_name}.spv.h)
    add_custom_command(
      OUTPUT ${header}
      COMMAND ${GLSLANG_VALIDATOR} --quiet --target-env vulkan1.3 ${include_flags}
              --vn ${var_name}_spv -o ${header} ${abs}
      DEPENDS ${abs} ${shared_glsl} ${pass_headers}
      COMMENT "glslang ${file_name}"
      VERBATIM)
    list(APPEND headers ${header})
  endforeach()
  target_sources(${target} PRIVATE ${headers})
  target_include_directories(${target} PRIVATE ${CMAKE_CURRENT_BINARY_DIR}/generated)
endfunction()
