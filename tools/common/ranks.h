// Ranks: the processes a run spreads its work over — one (no MPI) or the ranks of mpirun
// (--mpi; solvers/mpi/mpi_population_exchange.h): ergo_population's bodies (body b on rank
// b mod size), ergo_sweep's cases. Everything that crosses ranks goes through here, so a
// tool reads the same in both modes.
#pragma once

#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "solvers/population_exchange.h"

namespace ergo {

class Ranks {
 public:
  // Single process, or (mpi) MPI_Init_thread with MPI_THREAD_MULTIPLE. Throws InputError if
  // `mpi` is asked of a build without Open MPI or the library gives less thread support;
  // `signal` is this process's stop flag.
  Ranks(bool mpi, int* argc, char*** argv, const std::atomic<bool>* signal);
  // One process, whatever launched it (work that rank 0 does alone).
  explicit Ranks(const std::atomic<bool>* signal);
  ~Ranks();  // MPI_Finalize
  Ranks(const Ranks&) = delete;
  Ranks& operator=(const Ranks&) = delete;

  bool mpi() const { return mpi_; }
  int rank() const { return rank_; }
  int size() const { return size_; }
  bool root() const { return rank_ == 0; }
  bool Owns(int body) const { return body % size_ == rank_; }
  // Ranks of this run on this machine (for the threads each may use).
  int local_size() const { return local_size_; }

  // A channel for one population objective (null without MPI: nothing to exchange).
  std::unique_ptr<PopulationExchange> NewExchange();
  // Element-wise sum over ranks of values each rank fills for its own bodies.
  void SumDisjoint(std::vector<double>* values);
  // The first rank's non-empty error (or ""), on every rank.
  std::string FirstError(const std::string& local_error);
  std::string Broadcast(const std::string& text);  // rank 0's text
  // Every rank's `text` in rank order, on rank 0 (empty elsewhere).
  std::vector<std::string> Gather(const std::string& text);
  void Barrier();
  // The stop that every rank agrees on (a signal on any rank, rank 0's wall-clock budget):
  // what the optimiser polls. Without MPI, the signal flag itself.
  const std::atomic<bool>& stop() const;
  void WishStop();  // rank 0's budget ran out
  // Payload bytes this rank has sent in reductions so far.
  long long BytesSent() const;
  // Ends every rank at once (an error only this rank saw after set-up).
  [[noreturn]] void Abort(int code);

 private:
  bool mpi_ = false;
  int rank_ = 0, size_ = 1, local_size_ = 1;
  const std::atomic<bool>* signal_;
  std::atomic<bool> wish_{false};
  struct Mpi;
  std::unique_ptr<Mpi> impl_;
};

}  // namespace ergo
