#include "accuracy.h"

#include <cstdio>

namespace fosssim::bench {

int run_accuracy_case() {
  std::printf("\n(accuracy table: to do)\n");
  return 0;
}

}  // namespace fosssim::bench
