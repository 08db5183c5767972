# Writes a C++ source holding the text of a seed file:
#   cmake -DINPUT=... -DOUTPUT=... [-DVARIABLE=kSeedCsv] -P embed_seed.cmake
# VARIABLE names the `const char* const` in highlift::componentdb::detail (default kSeedCsv, the
# component database's seed; kTubeSizesCsv holds the standard tube sizes).
# The text is split into chunks of adjacent raw string literals (each well below compiler limits).
include(${CMAKE_CURRENT_LIST_DIR}/../../cmake/RawStringLiteral.cmake)
if(NOT DEFINED VARIABLE)
  set(VARIABLE kSeedCsv)
endif()
file(READ "${INPUT}" text)
highlift_raw_string_literal("${text}" highlift_seed body ${INPUT})
file(WRITE "${OUTPUT}.tmp" "// Generated from ${INPUT} by componentdb/cmake/embed_seed.cmake. Do not edit.\nnamespace highlift::componentdb::detail {\nextern const char* const ${VARIABLE};\nconst char* const ${VARIABLE} =\n${body};\n}  // namespace highlift::componentdb::detail\n")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.tmp")
