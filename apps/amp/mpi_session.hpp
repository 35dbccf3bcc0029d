#pragma once
#include <cstddef>

namespace amp::cli {

// The MPI job `amp bench` runs in when launched by `mpirun -n P` (and built with MPI): rank r runs
// shard r/P, rank 0 merges. Without MPI, or outside mpirun, a session of one rank.
class MpiSession {
 public:
  MpiSession();  // MPI_Init when launched by an MPI launcher
  ~MpiSession();  // MPI_Finalize
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  std::size_t rank() const { return rank_; }
  std::size_t size() const { return size_; }
  bool active() const { return size_ > 1; }
  void barrier() const;
  // Every rank's flag ORed: did any rank fail or get interrupted?
  bool any(bool flag) const;

 private:
  std::size_t rank_ = 0;
  std::size_t size_ = 1;
  bool initialised_ = false;
};

}  // namespace amp::cli
