/* The winged-edge cube of the course notes ("Alas y celdas", seed 000): built from its six faces
 * with the slide's own edge numbering, then printed as the slide's Vertex-Edge, Face-Edge and
 * Edge-Edge tables (EPCW/ENCW/EPCCW/ENCCW/FCW/FCCW). Compare the output with the slide row by row.
 *
 * The seed gives no coordinates; these put every face counter-clockwise seen from outside. */
#include <stdio.h>
#include <stdlib.h>

#include <halfwing.h>

static const double positions[] = {0, 0, 0, 0, 1, 0, 1, 1, 0, 1, 0, 0,
                                   0, 1, 1, 0, 0, 1, 1, 0, 1, 1, 1, 1};
static const uint32_t face_sizes[] = {4, 4, 4, 4, 4, 4};
/* F1..F6, each starting at the corner where its ESTART edge leaves. */
static const uint32_t faces[] = {0, 1, 2, 3, 4, 5, 6, 7, 2, 7, 6, 3,
                                 0, 5, 4, 1, 0, 3, 6, 5, 4, 7, 2, 1};
/* E1..E12 as (VSTART, VEND), in the slide's order. */
static const uint32_t edges[] = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6,
                                 6, 7, 7, 4, 0, 5, 4, 1, 2, 7, 6, 3};

static int fail(const char *what, hw_status status) {
  char message[512];
  hw_last_error_message(message, sizeof message, NULL);
  fprintf(stderr, "%s: %s: %s\n", what, hw_status_str(status), message);
  return 1;
}

int main(void) {
  hw_winged *cube = NULL;
  size_t needed = 0;
  char *text;
  hw_status status = hw_winged_from_indexed_ordered(positions, 8, face_sizes, 6, faces, 24,
                                                    edges, 12, &cube);
  if (status != HW_OK) return fail("hw_winged_from_indexed_ordered", status);

  /* Ask for the size first, then print into a buffer of that size. */
  hw_winged_table(cube, HW_WTABLE_ALL, HW_WNAMING_CW_CCW, HW_TABLE_FORMAT_TEXT, NULL, 0, &needed);
  text = (char *)malloc(needed);
  if (text == NULL) return 1;
  status = hw_winged_table(cube, HW_WTABLE_ALL, HW_WNAMING_CW_CCW, HW_TABLE_FORMAT_TEXT, text,
                           needed, NULL);
  if (status != HW_OK) return fail("hw_winged_table", status);
  printf("V = %zu, E = %zu, F = %zu\n\n%s", hw_winged_n_vertices(cube), hw_winged_n_edges(cube),
         hw_winged_n_faces(cube), text);

  free(text);
  hw_winged_free(cube);
  return 0;
}
