# Source lists of the OpenGL/GLFW examples, for include() from the CMakeLists that builds them.
# Paths are absolute, so the including file may live anywhere.
set(HALFWING_EXAMPLES_SHARED_DIR "${CMAKE_CURRENT_LIST_DIR}/../shared")
# Helpers of both GLFW programs: shader build, mesh shaders, orbit camera, offscreen screenshots,
# and the dependency-free PNG writer (stored deflate blocks, CRC-32 and Adler-32 in the file).
set(HALFWING_EXAMPLE_GL_SOURCES
  "${HALFWING_EXAMPLES_SHARED_DIR}/gl_program.c"
  "${HALFWING_EXAMPLES_SHARED_DIR}/mesh_shader.c"
  "${HALFWING_EXAMPLES_SHARED_DIR}/orbit_camera.c"
  "${HALFWING_EXAMPLES_SHARED_DIR}/offscreen.c"
  "${HALFWING_EXAMPLES_SHARED_DIR}/png_write.c")
# The C++ viewer: a scene interface, the mesh and Voronoi scenes, the doctor's findings layer, GL
# object owners, and the window loop.
set(HALFWING_VIEWER_SOURCES
  "${CMAKE_CURRENT_LIST_DIR}/main.cpp"
  "${CMAKE_CURRENT_LIST_DIR}/findings_layer.cpp"
  "${CMAKE_CURRENT_LIST_DIR}/mesh_scene.cpp"
  "${CMAKE_CURRENT_LIST_DIR}/voronoi_scene.cpp")
