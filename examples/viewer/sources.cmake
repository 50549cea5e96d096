# Source lists of the OpenGL/GLFW examples, for include() from the CMakeLists that builds them.
# Paths are absolute, so the including file may live anywhere.
set(HALFWING_EXAMPLES_SHARED_DIR "${CMAKE_CURRENT_LIST_DIR}/../shared")
# Dependency-free PNG writer (stored deflate blocks, CRC-32 and Adler-32 computed in the file).
set(HALFWING_PNG_WRITE_SOURCES "${HALFWING_EXAMPLES_SHARED_DIR}/png_write.c")
# The small C GLFW program: OpenGL 3.3 core, Lambert + wireframe, orbit camera, --screenshot.
set(HALFWING_GLFW_VIEW_SOURCES "${CMAKE_CURRENT_LIST_DIR}/../c/glfw_view.c" ${HALFWING_PNG_WRITE_SOURCES})
