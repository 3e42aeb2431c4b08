#include "app/bench.h"

#include <cstdio>

namespace coilsim {
int runBench(const std::vector<std::string>&) {
  std::fprintf(stderr, "coilsim bench: the benchmark is being written (issue 2)\n");
  return 2;
}
}  // namespace coilsim
