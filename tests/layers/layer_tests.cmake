# The layers the build enforces (third_party/cmake/PdrtLayers.cmake), checked: a library's
# compile sees the headers of its own folder and of the layers below it, and a header of a
# layer above it is not found. Each case compiles a one-line probe with the include
# directories the library itself compiles with (check_include.cmake).
set(PDRT_LAYER_CASES
  # library                 header                                   expected
  "pdrt_sampling_core       sampling/core/point_set.h                 seen"
  "pdrt_sampling_core       sampling/generators/generator.h           refused"
  "pdrt_sampling_generators sampling/measures/min_distance.h          refused"
  "pdrt_sampling_measures   sampling/generators/generator.h           seen"
  "pdrt_sampling_measures   sampling/samplers/sample_table.h          refused"
  "pdrt_sampling_samplers   sampling/measures/min_distance.h          seen"
  "pdrt_sampling_samplers   sampling/analysis/chi_square.h            refused"
  "pdrt_sampling_analysis   renderer/image/image.h                    refused"
  "pdrt_image_io            sampling/core/point_set.h                 seen"
  "pdrt_image_io            renderer/scene/vec3.h                     refused"
  "pdrt_scene               renderer/image/image.h                    seen"
  "pdrt_scene               renderer/scene/pbrt/pbrt_matrix.h         seen"
  "pdrt_scene               renderer/render/film.h                    refused"
  "pdrt_assetgen            renderer/render/film.h                    refused"
  "pdrt_render              renderer/render/film.h                    seen"
  "pdrt_render              renderer/compare/seed_statistics.h        refused"
  "pdrt_compare             distributed/mpi_process_group.h           refused")
foreach(case ${PDRT_LAYER_CASES})
  string(REGEX REPLACE " +" ";" case "${case}")
  list(GET case 0 library)
  list(GET case 1 header)
  list(GET case 2 expected)
  get_filename_component(stem ${header} NAME_WE)
  set(name layers.${library}.${expected}.${stem})
  add_test(NAME ${name} COMMAND ${CMAKE_COMMAND} -DCXX=${CMAKE_CXX_COMPILER} -DSOURCE_DIR=${PROJECT_SOURCE_DIR}
    "-DINCLUDES=$<JOIN:$<TARGET_PROPERTY:${library},INCLUDE_DIRECTORIES>,|>" -DHEADER=${header} -DEXPECT=${expected}
    -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/layers/${name} -P ${CMAKE_CURRENT_LIST_DIR}/check_include.cmake)
endforeach()
# Every pdrt include in a layer names its header from the repository root, so that the include
# roots decide what it sees (a relative "../render/film.h" would go around them).
add_test(NAME layers.includes_from_root COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${PROJECT_SOURCE_DIR}
  -P ${CMAKE_CURRENT_LIST_DIR}/check_include_paths.cmake)
