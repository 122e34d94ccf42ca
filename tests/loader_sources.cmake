# The sources the scene, pbrt-v4, OBJ and PLY loaders need, and nothing that renders: shared by
# the AddressSanitizer build of the loader tests (tests/CMakeLists.txt) and the fuzzers
# (tests/fuzz/), which rebuild them with their own instrumentation. Everything else they use
# is header-only or a system library (PDRT_LOADER_LIBRARIES).
set(PDRT_SCENE_DIR ${PROJECT_SOURCE_DIR}/renderer/scene)
# Every source of the pbrt-v4 importer (renderer/scene/pbrt/), as renderer/CMakeLists.txt globs it.
file(GLOB PDRT_PBRT_SOURCES CONFIGURE_DEPENDS ${PDRT_SCENE_DIR}/pbrt/*.cpp)
set(PDRT_LOADER_SOURCES
  ${PDRT_PBRT_SOURCES}
  ${PDRT_SCENE_DIR}/scene_loader.cpp ${PDRT_SCENE_DIR}/json_document.cpp ${PDRT_SCENE_DIR}/json_locations.cpp
  ${PDRT_SCENE_DIR}/obj_loader.cpp ${PDRT_SCENE_DIR}/text_file.cpp ${PDRT_SCENE_DIR}/input_files.cpp ${PDRT_SCENE_DIR}/transform.cpp
  ${PDRT_SCENE_DIR}/material.cpp ${PDRT_SCENE_DIR}/asset_path.cpp ${PDRT_SCENE_DIR}/environment_image.cpp
  ${PDRT_SCENE_DIR}/texture_desc.cpp ${PDRT_SCENE_DIR}/crop_window.cpp ${PDRT_SCENE_DIR}/render_settings.cpp
  ${PROJECT_SOURCE_DIR}/renderer/image/image_module.cpp
  ${PROJECT_SOURCE_DIR}/sampling/core/printable.cpp ${PROJECT_SOURCE_DIR}/sampling/core/install_paths.cpp ${PROJECT_SOURCE_DIR}/sampling/core/warnings.cpp)
set(PDRT_LOADER_LIBRARIES nlohmann_json::nlohmann_json tinyobjloader::tinyobjloader assimp::assimp pdrt::opensubdiv
  ${CMAKE_DL_LIBS})
