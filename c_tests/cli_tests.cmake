# The `halfwing` command-line tool on models and point sets of the test data: every command,
# its help, its errors and its exit codes (cli_check.cmake runs one command and checks it).

set(_cli_scratch "${CMAKE_CURRENT_BINARY_DIR}/scratch/cli")
file(MAKE_DIRECTORY "${_cli_scratch}")
set(_meshes "${HALFWING_DATA_DIR}/meshes")
set(_points "${HALFWING_DATA_DIR}/points2d")

# halfwing_cli_test(NAME CODE ARGS... [STDOUT regex] [STDERR regex] [FILE path])
function(halfwing_cli_test name code)
  cmake_parse_arguments(PARSE_ARGV 2 T "" "STDOUT;STDERR;FILE" "ARGS")
  # add_test splits its arguments at semicolons: the list travels joined by '|'.
  string(REPLACE ";" "|" joined "${T_ARGS}")
  set(defines -DCLI=${HALFWING_CLI} "-DARGS=${joined}" -DEXPECT_CODE=${code})
  foreach(key STDOUT STDERR FILE)
    if(DEFINED T_${key})
      list(APPEND defines "-DEXPECT_${key}=${T_${key}}")
    endif()
  endforeach()
  add_test(NAME cli_${name}
           COMMAND "${CMAKE_COMMAND}" ${defines} -P "${CMAKE_CURRENT_SOURCE_DIR}/cli_check.cmake")
endfunction()

halfwing_cli_test(help 0 ARGS --help STDOUT "exit codes:.*2  usage error")
halfwing_cli_test(no_command 2 ARGS "" STDOUT "usage: halfwing COMMAND")
halfwing_cli_test(unknown_command 2 ARGS frobnicate STDERR "unknown command \"frobnicate\"")
foreach(command info doctor repair convert voronoi)
  halfwing_cli_test(${command}_help 0 ARGS ${command} --help STDOUT "usage: halfwing ${command}.*Exit codes")
endforeach()

halfwing_cli_test(info 0 ARGS info "${_meshes}/broken/cgal_cubes.off"
  STDOUT "vertices: 14\nfaces:    24\ncorners:  72\nbounding box: \\[0, 0, 0\\] to \\[2, 2, 1\\]\ndoctor: 1 component.*not a manifold")
halfwing_cli_test(info_missing_file 3 ARGS info "${_cli_scratch}/missing.obj"
  STDERR "cannot open '.*missing.obj'")
halfwing_cli_test(info_bad_index 3 ARGS info "${_meshes}/broken/tobj_invalid_index.obj"
  STDERR "tobj_invalid_index.obj: OBJ parse error at line 12")
halfwing_cli_test(info_unknown_format 3 ARGS info "${HALFWING_DATA_DIR}/MANIFEST.md"
  STDERR "MANIFEST.md")
halfwing_cli_test(info_two_models 2 ARGS info a.obj b.obj STDERR "expected MODEL")

halfwing_cli_test(doctor_clean 0 ARGS doctor "${_meshes}/closed/cgal_cube.off"
  STDOUT "a closed polyhedron")
halfwing_cli_test(doctor_defects 1 ARGS doctor "${_meshes}/broken/cgaltest_nm_edges_simple.off"
  STDOUT "not a closed polyhedron")
halfwing_cli_test(doctor_json 1 ARGS doctor "${_meshes}/open/cgal_triangle.off" --json
  STDOUT "^\\{\"closed_polyhedron\":false")
halfwing_cli_test(doctor_unknown_option 2 ARGS doctor --yaml x.off STDERR "unknown option --yaml")

halfwing_cli_test(repair 0 ARGS repair "${_meshes}/broken/cgal_cubes.off" "${_cli_scratch}/cubes.off"
  STDOUT "vertices: 14 in, [0-9]+ out: .*faces:    24 in, 24 out" FILE "${_cli_scratch}/cubes.off")
# The repaired cubes are two closed cubes, which still touch along the edge they shared.
halfwing_cli_test(repair_result_is_closed 1 ARGS doctor "${_cli_scratch}/cubes.off"
  STDOUT "2 components, 0 boundary loops; not a closed polyhedron: faces intersect each other")
set_tests_properties(cli_repair_result_is_closed PROPERTIES DEPENDS cli_repair)
halfwing_cli_test(repair_small_components 0
  ARGS repair "${_meshes}/broken/cgal_tetra_intersected_by_triangle.off" "${_cli_scratch}/tetra.ply" --small-faces 1
  STDOUT "removed faces \\(small component\\): 1")
halfwing_cli_test(repair_bad_tolerance 2
  ARGS repair "${_meshes}/broken/cgal_cubes.off" "${_cli_scratch}/x.off" --merge-relative 2
  STDERR "tolerance 2 refused")
halfwing_cli_test(repair_degenerate_faces 0
  ARGS repair "${_meshes}/broken/cgaltest_degtri_four.off" "${_cli_scratch}/degtri_four.off"
  STDOUT "removed faces \\(degenerate\\): 1")
halfwing_cli_test(repair_keep_degenerate_faces 0
  ARGS repair "${_meshes}/broken/cgaltest_degtri_four.off" "${_cli_scratch}/degtri_kept.off" --keep-degenerate-faces
  STDOUT "faces:    4 in, 4 out")
halfwing_cli_test(repair_t_vertices 0
  ARGS repair "${_meshes}/broken/cgal_degtri_sliding.off" "${_cli_scratch}/sliding.off"
  STDOUT "flipped edges: 1, split edges: 3, stitched edges: 1")
halfwing_cli_test(repair_keep_with_tolerance 2
  ARGS repair "${_meshes}/broken/cgal_cubes.off" "${_cli_scratch}/x.off" --keep-t-vertices --t-vertex-tolerance 1
  STDERR "--keep-t-vertices excludes --t-vertex-tolerance")
halfwing_cli_test(repair_bad_degenerate_tolerance 2
  ARGS repair "${_meshes}/broken/cgal_cubes.off" "${_cli_scratch}/x.off" --degenerate-tolerance -1
  STDERR "tolerance -1 refused")
halfwing_cli_test(repair_unknown_output_format 2
  ARGS repair "${_meshes}/broken/cgal_cubes.off" "${_cli_scratch}/x.stl" STDERR "x.stl: unknown output format")
halfwing_cli_test(repair_unwritable 4
  ARGS repair "${_meshes}/broken/cgal_cubes.off" "${_cli_scratch}/no/such/dir/x.off" STDERR "x.off")

halfwing_cli_test(convert_binary_ply 0 ARGS convert "${_meshes}/open/igl_beetle.off" "${_cli_scratch}/beetle.ply"
  FILE "${_cli_scratch}/beetle.ply")
halfwing_cli_test(convert_back 0 ARGS info "${_cli_scratch}/beetle.ply" STDOUT "faces:    [0-9]+")
set_tests_properties(cli_convert_back PROPERTIES DEPENDS cli_convert_binary_ply)
halfwing_cli_test(convert_ascii_ply 0 ARGS convert "${_meshes}/broken/c3d_teapot.obj" "${_cli_scratch}/teapot.ply" --ascii
  FILE "${_cli_scratch}/teapot.ply")
halfwing_cli_test(convert_binary_obj_refused 2 ARGS convert "${_meshes}/open/igl_beetle.off" "${_cli_scratch}/beetle.obj" --binary
  STDERR "OBJ is written as text only")
halfwing_cli_test(convert_missing_argument 2 ARGS convert "${_meshes}/open/igl_beetle.off" STDERR "expected IN OUT")

halfwing_cli_test(voronoi_xy_lloyd 0 ARGS voronoi "${_points}/cgal_blob00.xy" --lloyd 3 --svg "${_cli_scratch}/blob.svg"
  FILE "${_cli_scratch}/blob.svg")
halfwing_cli_test(voronoi_poly_clip 0 ARGS voronoi "${_points}/triangle_A.poly" --clip 0,0,1,1 --svg "${_cli_scratch}/a.svg"
  FILE "${_cli_scratch}/a.svg")
halfwing_cli_test(voronoi_json 0 ARGS voronoi "${_points}/delaunator_ukraine.json" --svg "${_cli_scratch}/ukraine.svg"
  FILE "${_cli_scratch}/ukraine.svg")
halfwing_cli_test(voronoi_needs_svg 2 ARGS voronoi "${_points}/cgal_blob00.xy" STDERR "--svg OUT is required")
halfwing_cli_test(voronoi_bad_clip 2 ARGS voronoi "${_points}/cgal_blob00.xy" --clip 0,0,1 --svg x.svg STDERR "expected x0,y0,x1,y1")
halfwing_cli_test(voronoi_empty_clip 5 ARGS voronoi "${_points}/cgal_blob00.xy" --clip 0,0,0,1 --svg "${_cli_scratch}/e.svg"
  STDERR "cgal_blob00.xy: clip region is degenerate")
halfwing_cli_test(voronoi_not_points 3 ARGS voronoi "${_meshes}/open/cgal_triangle.off" --svg x.svg STDERR "unknown point format")

# Output into a reader that stops early (here one that reads nothing) ends the tool quietly, as
# other command-line tools end: no panic message about the failed write.
add_test(NAME cli_closed_pipe
         COMMAND sh -c "\"$0\" doctor \"$1\" --json | true" "${HALFWING_CLI}"
                 "${_meshes}/broken/c3d_teapot.obj")
set_tests_properties(cli_closed_pipe PROPERTIES
                     FAIL_REGULAR_EXPRESSION "panicked|failed printing|Broken pipe")
