#include "mpi_session.hpp"

#include <cstdlib>

#ifdef AMP_WITH_MPI
#include <mpi.h>
#endif

namespace amp::cli {

namespace {
// Set by Open MPI's and MPICH's (PMI) launchers: initialise MPI only when started by one, so a plain
// `amp bench` never touches MPI.
bool launched_by_mpi() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"}) {
    if (std::getenv(v) != nullptr) return true;
  }
  return false;
}
}  // namespace

MpiSession::MpiSession() {
#ifdef AMP_WITH_MPI
  if (!launched_by_mpi()) return;
  MPI_Init(nullptr, nullptr);
  initialised_ = true;
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  rank_ = static_cast<std::size_t>(rank);
  size_ = static_cast<std::size_t>(size);
#else
  (void)launched_by_mpi;
#endif
}

MpiSession::~MpiSession() {
#ifdef AMP_WITH_MPI
  if (initialised_) MPI_Finalize();
#endif
}

void MpiSession::barrier() const {
#ifdef AMP_WITH_MPI
  if (initialised_) MPI_Barrier(MPI_COMM_WORLD);
#endif
}

bool MpiSession::any(bool flag) const {
#ifdef AMP_WITH_MPI
  if (initialised_) {
    int mine = flag ? 1 : 0, all = 0;
    MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    return all != 0;
  }
#endif
  return flag;
}

}  // namespace amp::cli
