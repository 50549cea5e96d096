// The command line of the soup benchmarks (doctor_compare, repair_compare):
// `[--quick] [--repeats N] [model files...]`, and the models it names.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "models.hpp"

namespace bench {

struct options {
  bool quick = false;  ///< One run on a small torus: a smoke test of the harness.
  int repeats = 5;     ///< Runs per measurement, the best one kept.
  std::vector<std::string> files;
};

/// Parses the command line into `out`; false, after printing the usage, on an unknown option.
inline bool parse_options(int argc, char** argv, options& out) {
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0) {
      out.quick = true;
    } else if (std::strcmp(argv[i], "--repeats") == 0 && i + 1 < argc) {
      out.repeats = std::max(1, std::atoi(argv[++i]));
    } else if (argv[i][0] == '-') {
      std::fprintf(stderr, "usage: %s [--quick] [--repeats N] [model files...]\n", argv[0]);
      return false;
    } else {
      out.files.push_back(argv[i]);
    }
  }
  if (out.quick) out.repeats = 1;
  return true;
}

/// Calls `compare(model, repeats)` on the generated ~1M-triangle torus (a small one with
/// --quick), then on every model file named.
template <class Compare>
void compare_models(const options& opts, Compare compare) {
  const uint32_t n = opts.quick ? 100 : 708;
  compare(torus(n, n, true), opts.repeats);
  for (const std::string& file : opts.files) compare(read_file(file), opts.repeats);
}

}  // namespace bench
