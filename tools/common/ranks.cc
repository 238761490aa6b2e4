#include "tools/common/ranks.h"

#include <cstdlib>
#include <string>

#include "ergo/mesh/input_error.h"

#ifdef ERGO_HAVE_MPI
#include <mpi.h>

#include "solvers/mpi/mpi_population_exchange.h"
#endif

namespace ergo {

#ifdef ERGO_HAVE_MPI
struct Ranks::Mpi {
  AgreedStop stop;
};
#else
struct Ranks::Mpi {};
#endif

Ranks::Ranks(const std::atomic<bool>* signal) : signal_(signal) {}

Ranks::Ranks(bool mpi, int* argc, char*** argv, const std::atomic<bool>* signal)
    : mpi_(mpi), signal_(signal) {
  const char* world = std::getenv("OMPI_COMM_WORLD_SIZE");
  if (!mpi && world && std::atoi(world) > 1)
    throw InputError("--mpi", "", std::string("is off, but mpirun started ") + world + " ranks",
                     "add --mpi (or run one process without mpirun)");
#ifdef ERGO_HAVE_MPI
  if (!mpi) return;
  int provided = 0;
  MPI_Init_thread(argc, argv, MPI_THREAD_MULTIPLE, &provided);
  impl_ = std::make_unique<Mpi>();
  impl_->stop.signal = signal;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  MPI_Comm local;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &local);
  MPI_Comm_size(local, &local_size_);
  MPI_Comm_free(&local);
  if (provided < MPI_THREAD_MULTIPLE) {
    MPI_Finalize();
    throw InputError("--mpi", "", "the MPI library does not support MPI_THREAD_MULTIPLE",
                     "use Open MPI (apt-get install openmpi-bin libopenmpi-dev)");
  }
#else
  if (mpi)
    throw InputError("--mpi", "", "this ergo_population was built without MPI",
                     "apt-get install openmpi-bin libopenmpi-dev, then configure and build again");
#endif
}

Ranks::~Ranks() {
#ifdef ERGO_HAVE_MPI
  if (impl_) {
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (!finalized) MPI_Finalize();
  }
#endif
}

std::unique_ptr<PopulationExchange> Ranks::NewExchange() {
#ifdef ERGO_HAVE_MPI
  if (impl_) return std::make_unique<MpiPopulationExchange>(MPI_COMM_WORLD, &impl_->stop);
#endif
  return nullptr;
}

void Ranks::SumDisjoint(std::vector<double>* values) {
#ifdef ERGO_HAVE_MPI
  if (impl_)
    MPI_Allreduce(MPI_IN_PLACE, values->data(), static_cast<int>(values->size()), MPI_DOUBLE,
                  MPI_SUM, MPI_COMM_WORLD);
#endif
}

std::string Ranks::FirstError(const std::string& local_error) {
#ifdef ERGO_HAVE_MPI
  if (impl_) return FirstErrorOnAnyRank(MPI_COMM_WORLD, local_error);
#endif
  return local_error;
}

std::string Ranks::Broadcast(const std::string& text) {
#ifdef ERGO_HAVE_MPI
  if (impl_) return BroadcastString(MPI_COMM_WORLD, 0, text);
#endif
  return text;
}

std::vector<std::string> Ranks::Gather(const std::string& text) {
#ifdef ERGO_HAVE_MPI
  if (impl_) return GatherStrings(MPI_COMM_WORLD, text);
#endif
  return {text};
}

void Ranks::Barrier() {
#ifdef ERGO_HAVE_MPI
  if (impl_) MPI_Barrier(MPI_COMM_WORLD);
#endif
}

const std::atomic<bool>& Ranks::stop() const {
#ifdef ERGO_HAVE_MPI
  if (impl_) return impl_->stop.agreed;
#endif
  return *signal_;
}

void Ranks::WishStop() {
#ifdef ERGO_HAVE_MPI
  if (impl_) impl_->stop.wish = true;
#endif
}

long long Ranks::BytesSent() const {
#ifdef ERGO_HAVE_MPI
  if (impl_) return MpiPopulationExchange::BytesSent();
#endif
  return 0;
}

void Ranks::Abort(int code) {
#ifdef ERGO_HAVE_MPI
  if (impl_) MPI_Abort(MPI_COMM_WORLD, code);
#endif
  std::exit(code);
}

}  // namespace ergo
