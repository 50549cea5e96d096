// The winged-edge structure from C++: the cube of the course notes built with halfwing.hpp from
// its faces (edges numbered as the "Creación a partir de malla indexada" slide creates them),
// printed with the other slide's column names (Vi Vf Cd Ci Ada Ads Aia Ais), then walked with
// range-for: the vertices of each face and the faces around each vertex.
#include <cstdio>
#include <halfwing.hpp>

int main() {
  try {
    const hw::winged cube = hw::winged::from_indexed(
        {0, 0, 0, 0, 1, 0, 1, 1, 0, 1, 0, 0, 0, 1, 1, 0, 0, 1, 1, 0, 1, 1, 1, 1},
        {4, 4, 4, 4, 4, 4},
        {0, 1, 2, 3, 4, 5, 6, 7, 2, 7, 6, 3, 0, 5, 4, 1, 0, 3, 6, 5, 4, 7, 2, 1});
    std::printf("%s\n", cube.table(hw::WTable::Edges, hw::WNaming::DirectInverse).c_str());

    for (uint32_t f = 0; f < cube.n_faces(); ++f) {
      std::printf("face %u:", f);
      for (hw_wvertex v : cube.face_vertices(hw_wface{f})) std::printf(" v%u", v.idx);
      std::printf("\n");
    }
    for (uint32_t v = 0; v < cube.n_vertices(); ++v) {
      std::printf("around vertex %u:", v);
      for (hw_wface f : cube.vertex_faces(hw_wvertex{v})) std::printf(" f%u", f.idx);
      std::printf("\n");
    }
  } catch (const hw::error& e) {
    std::fprintf(stderr, "halfwing: %s\n", e.what());
    return 1;
  }
  return 0;
}
