#include "ergo/equilibrium/single_threaded_blas.h"

#include <dlfcn.h>

namespace ergo {

SingleThreadedBlas::SingleThreadedBlas() {
  set_ = reinterpret_cast<void (*)(int)>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  auto get = reinterpret_cast<int (*)()>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  if (!set_ || !get) {
    set_ = nullptr;
    return;
  }
  previous_ = get();
  set_(1);
}

SingleThreadedBlas::~SingleThreadedBlas() {
  if (set_) set_(previous_);
}

}  // namespace ergo
