// SingleThreadedBlas: OpenBLAS limited to one thread for a scope. Where several equilibria
// run side by side in threads (placements, probes, a population's bodies), a threaded BLAS
// under each sparse Cholesky only adds contention: OpenBLAS' pthread build serialises
// concurrent callers and spins its workers (measured on 2 busy cores, 17 bump evaluations
// in 8 probe threads: 34 s with OpenBLAS' threads, 2.4 s with one). And a product split
// over a different number of threads may round differently, so one thread also makes an
// equilibrium's bits independent of how many run beside it. Looked up at run time: a no-op
// for any other BLAS. Process-wide (OpenBLAS has one setting); nest freely, restores on exit.
#pragma once

namespace ergo {

class SingleThreadedBlas {
 public:
  SingleThreadedBlas();
  ~SingleThreadedBlas();
  SingleThreadedBlas(const SingleThreadedBlas&) = delete;
  SingleThreadedBlas& operator=(const SingleThreadedBlas&) = delete;

 private:
  void (*set_)(int) = nullptr;
  int previous_ = 1;
};

}  // namespace ergo
