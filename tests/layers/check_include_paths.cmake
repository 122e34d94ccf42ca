# layers.includes_from_root: every quoted include in sampling/, renderer/ and distributed/
# names its header from the repository root (sampling/..., renderer/..., distributed/...).
file(GLOB_RECURSE files ${SOURCE_DIR}/sampling/*.h ${SOURCE_DIR}/sampling/*.cpp ${SOURCE_DIR}/renderer/*.h
  ${SOURCE_DIR}/renderer/*.cpp ${SOURCE_DIR}/distributed/*.h ${SOURCE_DIR}/distributed/*.cpp)
set(bad)
foreach(f ${files})
  file(STRINGS ${f} lines REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
  foreach(line ${lines})
    if(NOT line MATCHES "\"(sampling|renderer|distributed)/[^\"]*\"" OR line MATCHES "\\.\\./")
      file(RELATIVE_PATH rel ${SOURCE_DIR} ${f})
      list(APPEND bad "${rel}: ${line}")
    endif()
  endforeach()
endforeach()
if(bad)
  string(REPLACE ";" "\n" bad "${bad}")
  message(FATAL_ERROR "includes not from the repository root (they would go around the layers' include roots):\n${bad}")
endif()
