#include "debrisflow/exec/parallel.hpp"
#include <omp.h>

namespace debrisflow::exec {
int max_threads() {
    return omp_get_max_threads();
}
void set_threads(int n) {
    if (n > 0) omp_set_num_threads(n);
}
} // namespace debrisflow::exec
