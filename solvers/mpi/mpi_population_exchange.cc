#include "solvers/mpi/mpi_population_exchange.h"

#include <algorithm>

#include <glog/logging.h>

namespace ergo {
namespace {

std::atomic<long long> bytes_sent{0};

}  // namespace

MpiPopulationExchange::MpiPopulationExchange(MPI_Comm comm, AgreedStop* stop) : stop_(stop) {
  CHECK_EQ(MPI_Comm_dup(comm, &comm_), MPI_SUCCESS);
}

MpiPopulationExchange::~MpiPopulationExchange() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (!finalized && comm_ != MPI_COMM_NULL) MPI_Comm_free(&comm_);
}

void MpiPopulationExchange::SumDisjoint(std::vector<double>* values) {
  // The stop wish rides along as one more slot: > 0 after the sum if any rank wished.
  values->push_back(stop_ && stop_->Wished() ? 1.0 : 0.0);
  CHECK_EQ(MPI_Allreduce(MPI_IN_PLACE, values->data(), static_cast<int>(values->size()), MPI_DOUBLE,
                         MPI_SUM, comm_),
           MPI_SUCCESS);
  bytes_sent += static_cast<long long>(values->size() * sizeof(double));
  if (stop_ && values->back() > 0) stop_->agreed = true;
  values->pop_back();
}

void MpiPopulationExchange::MaxBytes(std::vector<unsigned char>* bytes) {
  CHECK_EQ(MPI_Allreduce(MPI_IN_PLACE, bytes->data(), static_cast<int>(bytes->size()),
                         MPI_UNSIGNED_CHAR, MPI_MAX, comm_),
           MPI_SUCCESS);
  bytes_sent += static_cast<long long>(bytes->size());
}

std::unique_ptr<PopulationExchange> MpiPopulationExchange::Clone() const {
  return std::make_unique<MpiPopulationExchange>(comm_, stop_);
}

long long MpiPopulationExchange::BytesSent() { return bytes_sent.load(); }

std::string FirstErrorOnAnyRank(MPI_Comm comm, const std::string& local_error) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  int size = 1;
  MPI_Comm_size(comm, &size);
  // The lowest rank with an error, then its message broadcast from it.
  int mine = local_error.empty() ? size : rank, first = size;
  MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, comm);
  if (first == size) return "";
  return BroadcastString(comm, first, local_error);
}

std::string BroadcastString(MPI_Comm comm, int root, const std::string& text) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  int length = static_cast<int>(text.size());
  MPI_Bcast(&length, 1, MPI_INT, root, comm);
  std::string copy = rank == root ? text : std::string(static_cast<size_t>(length), ' ');
  MPI_Bcast(copy.data(), length, MPI_CHAR, root, comm);
  return copy;
}

std::vector<std::string> GatherStrings(MPI_Comm comm, const std::string& text) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  int length = static_cast<int>(text.size());
  std::vector<int> lengths(static_cast<size_t>(size)), offsets(static_cast<size_t>(size));
  MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, comm);
  std::string all;
  if (rank == 0) {
    for (int r = 1; r < size; ++r) offsets[r] = offsets[r - 1] + lengths[r - 1];
    all.resize(static_cast<size_t>(offsets.back() + lengths.back()));
  }
  MPI_Gatherv(text.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR,
              0, comm);
  std::vector<std::string> texts;
  if (rank == 0)
    for (int r = 0; r < size; ++r) texts.push_back(all.substr(offsets[r], lengths[r]));
  return texts;
}

}  // namespace ergo
