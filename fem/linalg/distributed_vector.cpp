#include "fem/linalg/distributed_vector.hpp"

#include "fem/core/error.hpp"
#include "fem/linalg/communicator.hpp"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace bipot {

DistributedVector::DistributedVector(const DofDistribution& dist)
    : dist_(dist), owned_(static_cast<std::size_t>(dist.num_owned_dofs()), 0.0) {
  if (dist.size() != mpi_size())
    throw Error("DistributedVector: DofDistribution made for " + std::to_string(dist.size()) +
                " ranks used on " + std::to_string(mpi_size()));
}

void DistributedVector::set_zero() {
  std::fill(owned_.begin(), owned_.end(), 0.0);
  pending_.clear();
}

void DistributedVector::add(Index global, double value) {
  if (global < 0) return;
  const Index local = global - dist_.first_owned_dof();
  if (local >= 0 && local < num_owned()) {
    owned_[local] += value;
    return;
  }
  if (global >= num_global())
    throw Error("DistributedVector::add: index " + std::to_string(global) + " >= size " +
                std::to_string(num_global()));
  pending_.emplace_back(global, value);
}

void DistributedVector::add(const Index* dofs, int n, const double* values) {
  for (int i = 0; i < n; ++i)
    add(dofs[i], values[i]);
}

void DistributedVector::finish_assembly() {
  const int size = dist_.size();
  if (size == 1) return; // nothing can be pending with one rank
  // Combine repeated indices first: a boundary entry is typically hit by several cells.
  std::sort(pending_.begin(), pending_.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Index> send_index;
  std::vector<double> send_value;
  std::vector<int> send_counts(size, 0);
  for (const auto& [index, value] : pending_) {
    if (!send_index.empty() && send_index.back() == index) {
      send_value.back() += value;
      continue;
    }
    send_index.push_back(index);
    send_value.push_back(value);
    ++send_counts[dist_.owner_of_dof(index)]; // ascending indices => grouped by owner
  }
  pending_.clear();
  std::vector<int> recv_counts(size, 0);
  MPI_Alltoall(send_counts.data(), 1, MPI_INT, recv_counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  std::vector<int> sdispl(size, 0), rdispl(size, 0);
  for (int p = 1; p < size; ++p) {
    sdispl[p] = sdispl[p - 1] + send_counts[p - 1];
    rdispl[p] = rdispl[p - 1] + recv_counts[p - 1];
  }
  const int n_recv = rdispl[size - 1] + recv_counts[size - 1];
  std::vector<Index> recv_index(n_recv);
  std::vector<double> recv_value(n_recv);
  MPI_Alltoallv(send_index.data(), send_counts.data(), sdispl.data(), MPI_INT64_T,
                recv_index.data(), recv_counts.data(), rdispl.data(), MPI_INT64_T, MPI_COMM_WORLD);
  MPI_Alltoallv(send_value.data(), send_counts.data(), sdispl.data(), MPI_DOUBLE, recv_value.data(),
                recv_counts.data(), rdispl.data(), MPI_DOUBLE, MPI_COMM_WORLD);
  const Index first = first_owned();
  for (int k = 0; k < n_recv; ++k)
    owned_[recv_index[k] - first] += recv_value[k];
}

void DistributedVector::set_owned(Index global, double value) {
  if (!dist_.owns_dof(global))
    throw Error("DistributedVector::set_owned: index " + std::to_string(global) +
                " is not owned by rank " + std::to_string(dist_.rank()));
  owned_[global - first_owned()] = value;
}

double DistributedVector::get_owned(Index global) const {
  if (!dist_.owns_dof(global))
    throw Error("DistributedVector::get_owned: index " + std::to_string(global) +
                " is not owned by rank " + std::to_string(dist_.rank()));
  return owned_[global - first_owned()];
}

std::vector<double> DistributedVector::gather_all() const {
  return bipot::gather_all(owned_); // blocks are contiguous and in rank order
}

double DistributedVector::norm2() const {
  double local = 0;
  for (double v : owned_)
    local += v * v;
  return std::sqrt(sum_all(local));
}

double DistributedVector::dot(const DistributedVector& other) const {
  check_same_layout(other, "dot");
  double local = 0;
  for (std::size_t i = 0; i < owned_.size(); ++i)
    local += owned_[i] * other.owned_[i];
  return sum_all(local);
}

void DistributedVector::axpy(double a, const DistributedVector& x) {
  check_same_layout(x, "axpy");
  for (std::size_t i = 0; i < owned_.size(); ++i)
    owned_[i] += a * x.owned_[i];
}

void DistributedVector::scale(double a) {
  for (double& v : owned_)
    v *= a;
}

void DistributedVector::copy(const DistributedVector& other) {
  check_same_layout(other, "copy");
  owned_ = other.owned_;
}

void DistributedVector::check_same_layout(const DistributedVector& other, const char* what) const {
  if (other.dist_ != dist_)
    throw Error(std::string("DistributedVector::") + what + ": vectors have different layouts");
}

} // namespace bipot
