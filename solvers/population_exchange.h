// PopulationExchange: how the bodies of a PopulationObjective that live in other processes
// (MPI ranks, solvers/mpi_population_exchange.h) send their share of an evaluation. Every
// process runs the same program on the same design; each evaluates its own bodies and puts
// their figures in its slots of one buffer, zeros elsewhere, and SumDisjoint adds the
// buffers of all processes. A slot is non-zero in one process only, so the sum is exact in
// any order (x + 0 = x): every process then holds the same bits, and the aggregate, summed
// in body order, is the single-process one bit for bit.
#pragma once

#include <memory>
#include <vector>

namespace ergo {

class PopulationExchange {
 public:
  virtual ~PopulationExchange() = default;
  // Element-wise sum over the processes, in place (the same length everywhere).
  virtual void SumDisjoint(std::vector<double>* values) = 0;
  // Element-wise maximum over the processes, in place (failure messages: each body's bytes
  // are written by its own process only).
  virtual void MaxBytes(std::vector<unsigned char>* bytes) = 0;
  // An independent channel for a copy of the objective (probes evaluated side by side keep
  // their exchanges apart). Called by every process at the same point of the program.
  virtual std::unique_ptr<PopulationExchange> Clone() const = 0;
};

}  // namespace ergo
