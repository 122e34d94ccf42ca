# `cmake --install build [--prefix P]`: pdrt and everything it finds relative to itself
# (sampling/core/install_paths.h): P/bin/pdrt, P/lib/pdrt/<image module>, P/share/pdrt/{tables,
# assets,scripts,scenes}, P/share/doc/pdrt. Only what the demo's build (pdrt, pdrt_tables) makes.
install(TARGETS pdrt RUNTIME DESTINATION bin)
install(TARGETS pdrt_image LIBRARY DESTINATION lib/pdrt)
install(FILES ${PDRT_TABLE_FILES} DESTINATION share/pdrt/tables)
install(FILES ${PDRT_ASSET_DIR}/sky.exr DESTINATION share/pdrt/assets)
install(FILES ${PROJECT_SOURCE_DIR}/sampling/analysis/plot_analysis.py ${PROJECT_SOURCE_DIR}/renderer/compare/plot_compare.py
  DESTINATION share/pdrt/scripts)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/scenes/ DESTINATION share/pdrt/scenes)
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION share/doc/pdrt)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION share/doc/pdrt/docs)
