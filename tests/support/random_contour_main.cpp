// Writes random contours (random_contour.hpp) for other test programs, e.g. differential.py:
//   ncoffset_random_contours [--differential] SEED FIRST COUNT DECIMALS
// prints `description()` of contours FIRST .. FIRST + COUNT - 1, each followed by `end`.
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "support/random_contour.hpp"

int main(int argc, char** argv) {
  ncoffset::test::GeneratorOptions opt;
  int a = 1;
  if (a < argc && std::strcmp(argv[a], "--differential") == 0) {
    opt.differential = true;
    ++a;
  }
  if (argc - a != 4) {
    std::fprintf(stderr, "usage: %s [--differential] SEED FIRST COUNT DECIMALS\n", argv[0]);
    return 2;
  }
  const unsigned seed = static_cast<unsigned>(std::strtoul(argv[a], nullptr, 10));
  const int first = std::atoi(argv[a + 1]), count = std::atoi(argv[a + 2]);
  const int decimals = std::atoi(argv[a + 3]);
  for (int i = first; i < first + count; ++i) {
    const auto c = ncoffset::test::randomContour(seed, i, decimals, opt);
    std::fputs(ncoffset::test::description(c).c_str(), stdout);
    std::fputs("end\n", stdout);
  }
  return 0;
}
