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
  add_compile_options(-fsanitize=${CANDELA_SANITIZE} -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=${CANDELA_SANITIZE})
endif()
