// MpiPopulationExchange: a PopulationObjective's bodies spread over MPI ranks. Every rank runs
// the same program — the same optimiser on the same design, each evaluating its own bodies —
// and the exchange adds the ranks' buffers with MPI_Allreduce on a communicator of its own
// (MPI_Comm_dup per copy of the objective, so probes evaluated side by side in threads never
// mix their messages; MPI_THREAD_MULTIPLE). A slot of the buffer is non-zero on one rank
// only, so the reduction is exact and every rank holds the same bits (population_exchange.h).
//
// Ranks stay in step only while they take the same branches: the decisions every rank must
// share (stop on a signal, a wall-clock budget) go through AgreedStop, which each exchange
// updates from every rank's wish at every evaluation.
#pragma once

#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include <mpi.h>

#include "solvers/population_exchange.h"

namespace ergo {

// Whether any rank asked to stop, as all ranks agree after the same evaluation.
struct AgreedStop {
  const std::atomic<bool>* signal = nullptr;  // this rank's signal flag (may be null)
  std::atomic<bool> wish{false};              // this rank's other reasons (rank 0's clock)
  std::atomic<bool> agreed{false};  // any rank's, at the last exchange: what optimisers read
  bool Wished() const { return wish.load() || (signal && signal->load()); }
};

class MpiPopulationExchange : public PopulationExchange {
 public:
  // Duplicates `comm` (collective over it). `stop` may be null and must outlive this.
  MpiPopulationExchange(MPI_Comm comm, AgreedStop* stop);
  ~MpiPopulationExchange() override;
  MpiPopulationExchange(const MpiPopulationExchange&) = delete;
  MpiPopulationExchange& operator=(const MpiPopulationExchange&) = delete;

  void SumDisjoint(std::vector<double>* values) override;
  void MaxBytes(std::vector<unsigned char>* bytes) override;
  std::unique_ptr<PopulationExchange> Clone() const override;

  // Bytes this exchange and its copies sent per rank so far (the reductions' payloads).
  static long long BytesSent();

 private:
  MPI_Comm comm_ = MPI_COMM_NULL;
  AgreedStop* stop_;
};

// The message of the first rank (by rank) whose `local_error` is non-empty, on every rank; ""
// when none has one. For set-up steps that may throw on one rank only (a body that cannot be
// built): every rank then stops together instead of waiting for the others.
std::string FirstErrorOnAnyRank(MPI_Comm comm, const std::string& local_error);

// `text` as rank `root` has it, on every rank.
std::string BroadcastString(MPI_Comm comm, int root, const std::string& text);

// Every rank's `text`, in rank order, on rank 0 (empty elsewhere).
std::vector<std::string> GatherStrings(MPI_Comm comm, const std::string& text);

}  // namespace ergo
