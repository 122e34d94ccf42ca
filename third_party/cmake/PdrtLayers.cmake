# Layers the build enforces. Sources include pdrt headers by their path from the repository
# root ("renderer/scene/vec3.h"), but a layer's library does not see the repository root: its
# one include root is a generated folder, build/layers/<library>/, that holds a symbolic link
# to the library's own source folder and nothing else
# (build/layers/pdrt_scene/renderer/scene -> <source>/renderer/scene). Linking a layer below
# PUBLIC adds that layer's root, so a library sees its own headers and those of the layers it
# links; including a header of a layer above it, or of a layer it does not link, fails to
# compile ("No such file or directory"). The layers and their direction are in
# renderer/README.md and sampling/README.md; tests/layers/ checks that a back-include fails.
#
# Only the top of the tree (distributed/, app/, tests/, bench/ and the build-time generators)
# includes from the repository root, as before.

# Creates build/layers/<target>/<folder> -> <source>/<folder> and makes that root the target's
# PUBLIC include directory.
function(pdrt_layer_include_root target folder)
  set(root ${PROJECT_BINARY_DIR}/layers/${target})
  set(link ${root}/${folder})
  set(source ${PROJECT_SOURCE_DIR}/${folder})
  if(NOT IS_DIRECTORY ${source})
    message(FATAL_ERROR "pdrt_layer_include_root(${target}): no folder ${source}")
  endif()
  if(IS_SYMLINK ${link})
    file(READ_SYMLINK ${link} current)
    if(NOT current STREQUAL source)
      file(REMOVE ${link})
    endif()
  endif()
  if(NOT IS_SYMLINK ${link})
    get_filename_component(parent ${link} DIRECTORY)
    file(MAKE_DIRECTORY ${parent})
    file(CREATE_LINK ${source} ${link} SYMBOLIC)
  endif()
  target_include_directories(${target} PUBLIC ${root})
endfunction()

# A layer: a static library of the .cpp files of `folder` (and of FOLDERS, sub-folders that
# belong to it; less EXCLUDE, plus SOURCES) whose include root is its own folder alone, linked PUBLIC to the layers BELOW
# it and to the third-party targets in PUBLIC_LIBS / PRIVATE_LIBS.
function(pdrt_layer target folder)
  cmake_parse_arguments(L "" "" "FOLDERS;EXCLUDE;BELOW;PUBLIC_LIBS;PRIVATE_LIBS;SOURCES" ${ARGN})
  set(sources ${L_SOURCES})
  foreach(dir ${folder} ${L_FOLDERS})
    file(GLOB found CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${dir}/*.cpp)
    list(APPEND sources ${found})
  endforeach()
  if(L_EXCLUDE)
    list(REMOVE_ITEM sources ${L_EXCLUDE})
  endif()
  add_library(${target} STATIC ${sources})
  pdrt_layer_include_root(${target} ${folder})
  target_link_libraries(${target} PUBLIC ${L_BELOW} ${L_PUBLIC_LIBS} PRIVATE ${L_PRIVATE_LIBS})
  if(PDRT_PRECOMPILED_HEADERS)
    # One precompiled header for every layer: the first layer makes it, the others reuse it.
    get_property(pch GLOBAL PROPERTY PDRT_LAYER_PCH)
    if(pch)
      target_precompile_headers(${target} REUSE_FROM ${pch})
    else()
      target_precompile_headers(${target} PRIVATE <nlohmann/json.hpp> <algorithm> <cmath> <filesystem> <string> <vector>)
      set_property(GLOBAL PROPERTY PDRT_LAYER_PCH ${target})
    endif()
  endif()
endfunction()
