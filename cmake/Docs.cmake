# The C and C++ API reference (docs/Doxyfile) as the target halfwing_docs, when doxygen is
# installed: `cmake --build build --target halfwing_docs` writes build/docs/html/index.html.
# Like scripts/docs.sh, it fails on any warning.
find_package(Doxygen QUIET)
if(DOXYGEN_FOUND)
  add_custom_target(halfwing_docs
    COMMAND ${CMAKE_COMMAND} -E make_directory "${CMAKE_BINARY_DIR}/docs"
    COMMAND ${CMAKE_COMMAND} -E env "HALFWING_DOCS_OUTPUT=${CMAKE_BINARY_DIR}/docs"
            "${DOXYGEN_EXECUTABLE}" docs/Doxyfile
    WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}"
    COMMENT "C and C++ API reference: ${CMAKE_BINARY_DIR}/docs/html/index.html"
    VERBATIM)
endif()
