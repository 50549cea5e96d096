/* A negative control for the sanitizer runs: this program leaks a mesh on purpose, and CTest
 * expects LeakSanitizer to fail it. If it ever passes, the other tests' "no leak" means nothing
 * (as it would if halfwing's handle registry kept leaked objects reachable). */
#include "halfwing.h"

int main(void) {
  hw_mesh *leaked = hw_mesh_new();
  return leaked == NULL;
}
