# Installing the engine (`cmake --install`) and finding it from a game's own project:
#
#   find_package(Candela REQUIRED)
#   target_link_libraries(game PRIVATE Candela::runtime)
#
# The static libraries, their public headers and the `candela` executable are installed with
# an export set (Candela::ecs, ::content, ::physics, ::audio, ::gameui, ::render, ::ui, ::runtime)
# and a CandelaConfig.cmake that finds what the libraries link (Vulkan, GLFW, OpenEXR, ...). Shaders need no install:
# they are SPIR-V embedded in the library at build time (README, "Shaders").
include(CMakePackageConfigHelpers)

set(CANDELA_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/Candela)

# Each library is Candela::<name> both installed and in this tree (add_subdirectory).
set(candela_exported candela_ecs)
set_target_properties(candela_ecs PROPERTIES EXPORT_NAME ecs)
add_library(Candela::ecs ALIAS candela_ecs)
if(CANDELA_BUILD_GRAPHICS)
  foreach(name content physics audio gameui render ui runtime)
    set_target_properties(candela_${name} PROPERTIES EXPORT_NAME ${name})
    add_library(Candela::${name} ALIAS candela_${name})
    list(APPEND candela_exported candela_${name})
  endforeach()
  # ui's link to Debian's prebuilt ImGui (absolute library paths, system headers).
  set_target_properties(candela_imgui_core PROPERTIES EXPORT_NAME imgui_core)
  list(APPEND candela_exported candela_imgui_core)
  install(TARGETS candela RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()

install(TARGETS ${candela_exported} EXPORT CandelaTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
foreach(dir ecs content physics audio gameui render ui runtime)
  if(dir STREQUAL "ecs" OR CANDELA_BUILD_GRAPHICS)
    install(DIRECTORY ${PROJECT_SOURCE_DIR}/${dir}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  endif()
endforeach()
install(EXPORT CandelaTargets NAMESPACE Candela:: DESTINATION ${CANDELA_INSTALL_CMAKEDIR})

set(CANDELA_CONFIG_GRAPHICS ${CANDELA_BUILD_GRAPHICS})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/CandelaConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/package/CandelaConfig.cmake
                              INSTALL_DESTINATION ${CANDELA_INSTALL_CMAKEDIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/package/CandelaConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/package/CandelaConfig.cmake
              ${PROJECT_BINARY_DIR}/package/CandelaConfigVersion.cmake
        DESTINATION ${CANDELA_INSTALL_CMAKEDIR})

# In this build (the engine's own tree, or a game that add_subdirectory'd it),
# find_package(Candela) finds the targets defined above: CMake searches this redirect folder
# before anything installed.
file(WRITE ${CMAKE_FIND_PACKAGE_REDIRECTS_DIR}/candela-config.cmake
     "# Candela is part of this build; its Candela:: targets exist already.\n")
write_basic_package_version_file(${CMAKE_FIND_PACKAGE_REDIRECTS_DIR}/candela-config-version.cmake
                                 COMPATIBILITY SameMinorVersion)
