// How many threads OpenBLAS (under CHOLMOD's supernodal factorisation) may use. ergo keeps it
// at one unless told otherwise: its parallelism is OpenMP (assembly, contact) and threads
// over placements, probes and bodies, and OpenBLAS' own threads spin while they wait, which
// on a machine whose cores are busy (two tests side by side, a build beside a run) costs far
// more than they give. Measured on this 2-core machine with a build beside: the bump run of
// the resume test (40 evaluations, 2k vertices) took 75 s wall with OpenBLAS' two threads
// (solves 35.6 s, 13.8 s of system time) and 11.5 s with one (solves 1.5 s). A product split
// over a different number of threads also rounds differently, so one thread makes an
// equilibrium's bits independent of the machine's load. Looked up at run time: a no-op for
// any other BLAS.
#pragma once

namespace ergo {

// Once per process: OpenBLAS to ERGO_BLAS_THREADS threads if that variable is set, else to
// the OPENBLAS_NUM_THREADS / OPENBLAS's own choice if OPENBLAS_NUM_THREADS is set, else to 1.
// Called by SparseCholesky before its first factorisation.
void ApplyDefaultBlasThreads();

// OpenBLAS limited to one thread for a scope (equilibria side by side in threads: OpenBLAS'
// pthread build serialises concurrent callers and spins its workers; measured on 2 busy
// cores, 17 bump evaluations in 8 probe threads: 34 s with OpenBLAS' threads, 2.4 s with
// one). Process-wide (OpenBLAS has one setting); nests, restores on exit.
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
