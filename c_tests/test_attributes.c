/* add_face, corner normals and texture coordinates, and named attributes through the C API,
 * with every bad argument. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "check.h"

/* A unit square as two triangles added one by one: vertices 0 1 2 3 counter-clockwise. */
static hw_mesh *square(void) {
  static const double corners[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  hw_mesh *mesh = hw_mesh_new();
  hw_vertex v[4];
  hw_vertex first[3], second[3];
  hw_face f;
  int i;
  for (i = 0; i < 4; ++i) CHECK(hw_mesh_add_vertex(mesh, corners[i], &v[i]) == HW_OK);
  first[0] = v[0];
  first[1] = v[1];
  first[2] = v[2];
  second[0] = v[0];
  second[1] = v[2];
  second[2] = v[3];
  CHECK(hw_mesh_add_face(mesh, first, 3, &f) == HW_OK && f.idx == 0);
  CHECK(hw_mesh_add_face(mesh, second, 3, &f) == HW_OK && f.idx == 1);
  return mesh;
}

static void add_face_links_and_refuses(void) {
  hw_mesh *mesh = square();
  hw_vertex face[3];
  hw_face f;
  hw_halfedge h;
  f.idx = 77;
  CHECK(hw_mesh_n_faces(mesh) == 2 && hw_mesh_n_edges(mesh) == 5);
  CHECK(hw_mesh_check(mesh) == HW_OK);
  /* The loop starts at the first corner given. */
  f.idx = 1;
  h = hw_mesh_face_halfedge(mesh, f);
  CHECK(hw_mesh_he_origin(mesh, h).idx == 0 && hw_mesh_he_target(mesh, h).idx == 2);

  face[0].idx = 0;
  face[1].idx = 1;
  face[2].idx = 2;
  f.idx = 77;
  CHECK_STATUS(hw_mesh_add_face(mesh, face, 3, &f), HW_ERR_REFUSED, "complex edge");
  CHECK(f.idx == 77); /* outputs only on success */
  CHECK_STATUS(hw_mesh_add_face(mesh, face, 2, &f), HW_ERR_REFUSED, "at least 3");
  face[2].idx = 0;
  CHECK_STATUS(hw_mesh_add_face(mesh, face, 3, &f), HW_ERR_REFUSED, "repeated");
  face[2].idx = 40;
  CHECK_STATUS(hw_mesh_add_face(mesh, face, 3, &f), HW_ERR_INVALID_HANDLE, "out of range");
  CHECK_STATUS(hw_mesh_add_face(NULL, face, 3, &f), HW_ERR_NULL_ARGUMENT, "mesh");
  CHECK_STATUS(hw_mesh_add_face(mesh, NULL, 3, &f), HW_ERR_NULL_ARGUMENT, "vertices");
  CHECK_STATUS(hw_mesh_add_face(mesh, face, 3, NULL), HW_ERR_NULL_ARGUMENT, "out_face");
  CHECK(hw_mesh_n_faces(mesh) == 2 && hw_mesh_check(mesh) == HW_OK);
  hw_mesh_free(mesh);
}

static void corner_normals_and_uvs(void) {
  hw_mesh *mesh = square();
  size_t n = hw_mesh_n_halfedge_slots(mesh);
  double normals[30], uvs[20];
  const double *view = NULL;
  size_t len = 0;
  size_t i;
  CHECK(n == 10);
  CHECK_STATUS(hw_mesh_corner_normals_view(mesh, &view, &len), HW_ERR_NOT_FOUND, "no corner");
  CHECK(view == NULL && len == 0);
  for (i = 0; i < n; ++i) {
    normals[3 * i] = 0.0;
    normals[3 * i + 1] = 0.0;
    normals[3 * i + 2] = 1.0;
    uvs[2 * i] = (double)i;
    uvs[2 * i + 1] = 0.25;
  }
  CHECK(hw_mesh_corner_normals_set(mesh, normals, n) == HW_OK);
  CHECK(hw_mesh_corner_uvs_set(mesh, uvs, n) == HW_OK);
  CHECK(hw_mesh_corner_normals_view(mesh, &view, &len) == HW_OK && len == n);
  CHECK(view[3 * 4 + 2] == 1.0);
  CHECK(hw_mesh_corner_uvs_view(mesh, &view, &len) == HW_OK && len == n && view[2 * 7] == 7.0);

  CHECK_STATUS(hw_mesh_corner_normals_set(mesh, normals, n - 1), HW_ERR_INVALID_INPUT,
               "element slots");
  normals[5] = NAN;
  CHECK_STATUS(hw_mesh_corner_normals_set(mesh, normals, n), HW_ERR_INVALID_INPUT, "finite");
  /* Messages name the arguments as the C signatures spell them. */
  CHECK_STATUS(hw_mesh_corner_normals_set(mesh, NULL, n), HW_ERR_NULL_ARGUMENT, "`xyz`");
  CHECK_STATUS(hw_mesh_corner_uvs_set(mesh, NULL, n), HW_ERR_NULL_ARGUMENT, "`uv`");
  CHECK_STATUS(hw_mesh_corner_normals_set(NULL, normals, n), HW_ERR_NULL_ARGUMENT, "mesh");
  CHECK_STATUS(hw_mesh_corner_uvs_set(NULL, uvs, n), HW_ERR_NULL_ARGUMENT, "mesh");
  {
    const double *const kept_view = view;
    const size_t kept_len = len;
    CHECK_STATUS(hw_mesh_corner_uvs_view(NULL, &view, &len), HW_ERR_NULL_ARGUMENT, "mesh");
    CHECK_STATUS(hw_mesh_corner_uvs_view(mesh, NULL, &len), HW_ERR_NULL_ARGUMENT, "`out_uv`");
    CHECK_STATUS(hw_mesh_corner_uvs_view(mesh, &view, NULL), HW_ERR_NULL_ARGUMENT,
                 "`out_n_halfedges`");
    CHECK_STATUS(hw_mesh_corner_normals_view(NULL, &view, &len), HW_ERR_NULL_ARGUMENT, "mesh");
    CHECK_STATUS(hw_mesh_corner_normals_view(mesh, NULL, &len), HW_ERR_NULL_ARGUMENT,
                 "`out_xyz`");
    CHECK_STATUS(hw_mesh_corner_normals_view(mesh, &view, NULL), HW_ERR_NULL_ARGUMENT,
                 "`out_n_halfedges`");
    CHECK(view == kept_view && len == kept_len); /* outputs untouched on failure */
  }
  /* Corner normals are the half-edge attribute "hw:corner_normal": writable in place. */
  {
    void *data = NULL;
    CHECK(hw_mesh_attribute_data(mesh, HW_ELEMENT_KIND_HALFEDGE, "hw:corner_normal",
                                 HW_SCALAR_TYPE_F64, &data, &len) == HW_OK);
    CHECK(len == 3 * n);
    ((double *)data)[0] = -1.0;
    CHECK(hw_mesh_corner_normals_view(mesh, &view, &len) == HW_OK && view[0] == -1.0);
  }
  CHECK(hw_mesh_attribute_remove(mesh, HW_ELEMENT_KIND_HALFEDGE, "hw:corner_uv") == HW_OK);
  CHECK_STATUS(hw_mesh_corner_uvs_view(mesh, &view, &len), HW_ERR_NOT_FOUND, "texture");
  hw_mesh_free(mesh);
}

static void named_attributes(void) {
  hw_mesh *mesh = square();
  const void *view = NULL;
  void *data = NULL;
  size_t len = 0, count = 0, components = 0, needed = 0;
  hw_scalar_type type = 99;
  char name[16];
  float *colour;
  const float *shade;
  hw_vertex w;
  hw_edge diagonal;
  hw_face face0;
  static const double middle[3] = {0.5, 0.5, 0.0};

  CHECK(hw_mesh_attribute_add(mesh, HW_ELEMENT_KIND_VERTEX, "colour", HW_SCALAR_TYPE_F32, 3) ==
        HW_OK);
  CHECK(hw_mesh_attribute_add(mesh, HW_ELEMENT_KIND_FACE, "label", HW_SCALAR_TYPE_I32, 1) == HW_OK);
  CHECK(hw_mesh_attribute_add(mesh, HW_ELEMENT_KIND_EDGE, "crease", HW_SCALAR_TYPE_U32, 1) ==
        HW_OK);
  CHECK(hw_mesh_attribute_info(mesh, HW_ELEMENT_KIND_VERTEX, "colour", &type, &components) ==
        HW_OK);
  CHECK(type == HW_SCALAR_TYPE_F32 && components == 3);
  CHECK(hw_mesh_attribute_data(mesh, HW_ELEMENT_KIND_VERTEX, "colour", HW_SCALAR_TYPE_F32, &data,
                               &len) == HW_OK);
  CHECK(len == 12);
  colour = (float *)data;
  colour[0] = 1.0f;  /* vertex 0 red */
  colour[7] = 1.0f;  /* vertex 2 green */

  /* Splitting the diagonal 2-0 at its middle blends the two colours half and half. */
  face0.idx = 0;
  diagonal = hw_mesh_he_edge(
      mesh, hw_mesh_he_next(mesh, hw_mesh_he_next(mesh, hw_mesh_face_halfedge(mesh, face0))));
  CHECK(hw_mesh_split_edge(mesh, diagonal, middle, &w) == HW_OK);
  CHECK(hw_mesh_attribute_view(mesh, HW_ELEMENT_KIND_VERTEX, "colour", HW_SCALAR_TYPE_F32, &view,
                               &len) == HW_OK);
  CHECK(len == 15);
  shade = (const float *)view;
  CHECK(shade[3 * w.idx] == 0.5f && shade[3 * w.idx + 1] == 0.5f && shade[3 * w.idx + 2] == 0.0f);

  /* Listing. */
  CHECK(hw_mesh_n_attributes(mesh, HW_ELEMENT_KIND_VERTEX, &count) == HW_OK && count == 1);
  CHECK(hw_mesh_attribute_name(mesh, HW_ELEMENT_KIND_VERTEX, 0, name, sizeof name, &needed) ==
        HW_OK);
  CHECK(strcmp(name, "colour") == 0 && needed == 7);
  CHECK_STATUS(hw_mesh_attribute_name(mesh, HW_ELEMENT_KIND_VERTEX, 0, name, 3, &needed),
               HW_ERR_BUFFER_TOO_SMALL, "needed");
  CHECK_STATUS(hw_mesh_attribute_name(mesh, HW_ELEMENT_KIND_VERTEX, 1, name, sizeof name, &needed),
               HW_ERR_NOT_FOUND, "does not exist");

  /* Bad arguments: each refused with its status, nothing changed. */
  CHECK_STATUS(hw_mesh_attribute_add(mesh, HW_ELEMENT_KIND_VERTEX, "colour", HW_SCALAR_TYPE_F64, 1),
               HW_ERR_INVALID_INPUT, "exists already");
  CHECK_STATUS(
      hw_mesh_attribute_add(mesh, HW_ELEMENT_KIND_HALFEDGE, "hw:mine", HW_SCALAR_TYPE_F64, 1),
      HW_ERR_INVALID_INPUT, "reserved");
  CHECK_STATUS(hw_mesh_attribute_add(mesh, HW_ELEMENT_KIND_VERTEX, "", HW_SCALAR_TYPE_F64, 1),
               HW_ERR_INVALID_INPUT, "empty");
  CHECK_STATUS(hw_mesh_attribute_add(mesh, HW_ELEMENT_KIND_VERTEX, "w", HW_SCALAR_TYPE_F64, 0),
               HW_ERR_INVALID_INPUT, "components");
  CHECK_STATUS(hw_mesh_attribute_add(mesh, HW_ELEMENT_KIND_VERTEX, "w", HW_SCALAR_TYPE_F64, 17),
               HW_ERR_INVALID_INPUT, "components");
  CHECK_STATUS(hw_mesh_attribute_add(mesh, HW_ELEMENT_KIND_VERTEX, "w", 9, 1), HW_ERR_INVALID_INPUT,
               "scalar type");
  CHECK_STATUS(hw_mesh_attribute_add(mesh, 7, "w", HW_SCALAR_TYPE_F64, 1), HW_ERR_INVALID_INPUT,
               "element kind");
  CHECK_STATUS(hw_mesh_attribute_add(mesh, HW_ELEMENT_KIND_VERTEX, "\xff", HW_SCALAR_TYPE_F64, 1),
               HW_ERR_INVALID_INPUT, "UTF-8");
  CHECK_STATUS(hw_mesh_attribute_add(NULL, HW_ELEMENT_KIND_VERTEX, "w", HW_SCALAR_TYPE_F64, 1),
               HW_ERR_NULL_ARGUMENT, "mesh");
  CHECK_STATUS(hw_mesh_attribute_add(mesh, HW_ELEMENT_KIND_VERTEX, NULL, HW_SCALAR_TYPE_F64, 1),
               HW_ERR_NULL_ARGUMENT, "name");
  view = NULL;
  len = 99;
  CHECK_STATUS(hw_mesh_attribute_view(mesh, HW_ELEMENT_KIND_VERTEX, "colour", HW_SCALAR_TYPE_F64,
                                      &view, &len),
               HW_ERR_INVALID_INPUT, "not f64");
  CHECK(view == NULL && len == 99);
  CHECK_STATUS(
      hw_mesh_attribute_view(mesh, HW_ELEMENT_KIND_FACE, "colour", HW_SCALAR_TYPE_F32, &view, &len),
      HW_ERR_NOT_FOUND, "no face attribute");
  CHECK_STATUS(hw_mesh_attribute_view(mesh, HW_ELEMENT_KIND_VERTEX, "colour", HW_SCALAR_TYPE_F32,
                                      NULL, &len),
               HW_ERR_NULL_ARGUMENT, "out_data");
  CHECK_STATUS(
      hw_mesh_attribute_data(mesh, HW_ELEMENT_KIND_EDGE, "crease", HW_SCALAR_TYPE_I32, &data, &len),
      HW_ERR_INVALID_INPUT, "not i32");
  CHECK_STATUS(hw_mesh_attribute_info(mesh, HW_ELEMENT_KIND_EDGE, "nothing", &type, &components),
               HW_ERR_NOT_FOUND, "nothing");
  CHECK_STATUS(hw_mesh_n_attributes(mesh, HW_ELEMENT_KIND_VERTEX, NULL), HW_ERR_NULL_ARGUMENT,
               "out_count");
  CHECK_STATUS(hw_mesh_attribute_remove(mesh, HW_ELEMENT_KIND_FACE, "colour"), HW_ERR_NOT_FOUND,
               "colour");
  {
    /* NULL mesh or name, unknown kinds, an index past the last and NULL outputs: refused, the
     * outputs untouched, the attribute still there. */
    hw_scalar_type unset_type = 99;
    size_t unset_components = 4242, unset_len = 4242, unset_needed = 4242;
    void *unset_data = NULL;
    char unset_name[4] = "abc";
    CHECK_STATUS(hw_mesh_attribute_info(NULL, HW_ELEMENT_KIND_VERTEX, "colour", &unset_type,
                                        &unset_components),
                 HW_ERR_NULL_ARGUMENT, "mesh");
    CHECK_STATUS(
        hw_mesh_attribute_info(mesh, HW_ELEMENT_KIND_VERTEX, NULL, &unset_type, &unset_components),
        HW_ERR_NULL_ARGUMENT, "name");
    CHECK_STATUS(hw_mesh_attribute_info(mesh, 7u, "colour", &unset_type, &unset_components),
                 HW_ERR_INVALID_INPUT, "element kind 7");
    CHECK(unset_type == 99 && unset_components == 4242);
    CHECK_STATUS(hw_mesh_attribute_remove(NULL, HW_ELEMENT_KIND_VERTEX, "colour"),
                 HW_ERR_NULL_ARGUMENT, "mesh");
    CHECK_STATUS(hw_mesh_attribute_remove(mesh, HW_ELEMENT_KIND_VERTEX, NULL), HW_ERR_NULL_ARGUMENT,
                 "name");
    CHECK_STATUS(hw_mesh_attribute_remove(mesh, 7u, "colour"), HW_ERR_INVALID_INPUT,
                 "element kind 7");
    CHECK_STATUS(hw_mesh_attribute_name(NULL, HW_ELEMENT_KIND_VERTEX, 0, unset_name,
                                        sizeof unset_name, &unset_needed),
                 HW_ERR_NULL_ARGUMENT, "mesh");
    CHECK_STATUS(hw_mesh_attribute_name(mesh, 7u, 0, unset_name, sizeof unset_name,
                                        &unset_needed),
                 HW_ERR_INVALID_INPUT, "element kind 7");
    CHECK_STATUS(hw_mesh_attribute_name(mesh, HW_ELEMENT_KIND_VERTEX, 1, unset_name,
                                        sizeof unset_name, &unset_needed),
                 HW_ERR_NOT_FOUND, "does not exist");
    CHECK(strcmp(unset_name, "abc") == 0 && unset_needed == 4242);
    CHECK_STATUS(hw_mesh_attribute_data(mesh, HW_ELEMENT_KIND_VERTEX, "colour", HW_SCALAR_TYPE_F32,
                                        NULL, &unset_len),
                 HW_ERR_NULL_ARGUMENT, "out_data");
    CHECK_STATUS(hw_mesh_attribute_data(mesh, HW_ELEMENT_KIND_VERTEX, "colour", HW_SCALAR_TYPE_F32,
                                        &unset_data, NULL),
                 HW_ERR_NULL_ARGUMENT, "out_len");
    CHECK(unset_data == NULL && unset_len == 4242);
    CHECK(hw_mesh_attribute_info(mesh, HW_ELEMENT_KIND_VERTEX, "colour", &unset_type,
                                 &unset_components) == HW_OK);
    CHECK(unset_type == HW_SCALAR_TYPE_F32 && unset_components == 3);
  }

  /* Compaction keeps the values with their elements. */
  CHECK(hw_mesh_attribute_data(mesh, HW_ELEMENT_KIND_FACE, "label", HW_SCALAR_TYPE_I32, &data,
                               &len) == HW_OK);
  CHECK(len == 2);
  ((int32_t *)data)[1] = -5;
  CHECK(hw_mesh_delete_face(mesh, face0, false) == HW_OK);
  CHECK(hw_mesh_garbage_collect(mesh, NULL) == HW_OK);
  CHECK(hw_mesh_attribute_view(mesh, HW_ELEMENT_KIND_FACE, "label", HW_SCALAR_TYPE_I32, &view,
                               &len) == HW_OK);
  CHECK(len == 1 && ((const int32_t *)view)[0] == -5);
  CHECK(hw_mesh_attribute_remove(mesh, HW_ELEMENT_KIND_FACE, "label") == HW_OK);
  CHECK(hw_mesh_n_attributes(mesh, HW_ELEMENT_KIND_FACE, &count) == HW_OK && count == 0);
  CHECK(hw_mesh_check(mesh) == HW_OK);
  hw_mesh_free(mesh);
}

/* An OBJ file's texture coordinates stay on the corners and are written back. */
static void obj_texture_coordinates_round_trip(void) {
  hw_mesh *mesh = NULL, *again = NULL;
  const double *uv = NULL, *uv_again = NULL;
  size_t n = 0, n_again = 0;
  const char *written = TEST_TMP_DIR "/test_attributes_spot.obj";
  CHECK(hw_mesh_read(HALFWING_DATA_DIR "/meshes/closed/c3d_spot.obj", HW_BUILD_POLICY_STRICT, &mesh,
                     NULL) == HW_OK);
  CHECK(hw_mesh_corner_uvs_view(mesh, &uv, &n) == HW_OK && n == 3 * 5856);
  CHECK(hw_mesh_write(mesh, written) == HW_OK);
  CHECK(hw_mesh_read(written, HW_BUILD_POLICY_STRICT, &again, NULL) == HW_OK);
  CHECK(hw_mesh_corner_uvs_view(again, &uv_again, &n_again) == HW_OK && n_again == n);
  CHECK(memcmp(uv, uv_again, 2 * n * sizeof(double)) == 0);
  remove(written);
  hw_mesh_free(again);
  hw_mesh_free(mesh);
}

int main(void) {
  add_face_links_and_refuses();
  corner_normals_and_uvs();
  named_attributes();
  obj_texture_coordinates_round_trip();
  return check_summary("test_attributes");
}
