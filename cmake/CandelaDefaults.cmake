# Shared compile settings: warnings, -Werror in CI, sanitizers.
function(candela_defaults target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                           -Wno-sign-conversion -Wnon-virtual-dtor
                                           # `VkFoo info{VK_STRUCTURE_TYPE_FOO}` zero-fills the rest
                                           # on purpose; that is the Vulkan idiom.
                                           -Wno-missing-field-initializers)
  if(CANDELA_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

if(CANDELA_SANITIZE)
  # -O1 -g1 (after the build type's -O2 -g, so they win): a sanitizer tree compiles about three
  # times faster (render/src/renderer.cpp under ASan: 19 s against 54 s), line tables still name
  # every frame of a report, and its tests' heavy work runs in lavapipe, not in this code.
  add_compile_options(-O1 -g1)
  add_compile_options(-fsanitize=${CANDELA_SANITIZE} -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=${CANDELA_SANITIZE})
endif()
