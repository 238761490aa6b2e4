#include "ergo/mesh/blas_threads.h"

#include <dlfcn.h>

#include <cstdlib>
#include <mutex>

namespace ergo {
namespace {

using SetThreads = void (*)(int);
using GetThreads = int (*)();

SetThreads Setter() {
  return reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
}
GetThreads Getter() {
  return reinterpret_cast<GetThreads>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
}

}  // namespace

void ApplyDefaultBlasThreads() {
  static std::once_flag once;
  std::call_once(once, [] {
    const SetThreads set = Setter();
    if (!set) return;
    if (const char* ergo = std::getenv("ERGO_BLAS_THREADS")) {
      const int threads = std::atoi(ergo);
      if (threads > 0) set(threads);
      return;
    }
    if (std::getenv("OPENBLAS_NUM_THREADS")) return;  // the user's choice
    set(1);
  });
}

SingleThreadedBlas::SingleThreadedBlas() {
  ApplyDefaultBlasThreads();  // first, so that the scope restores the default, not OpenBLAS'
  set_ = Setter();
  const GetThreads get = Getter();
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
