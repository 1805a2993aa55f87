#pragma once
/// Tiny collective helpers over MPI_COMM_WORLD. They need no Trilinos and no mpi.h in the
/// caller. When MPI has not been initialised (a serial unit test without ParallelEnvironment)
/// they behave as a single process: rank 0 of 1, reductions return their argument.

#include "fem/core/types.hpp"

#include <string>
#include <vector>

namespace bipot {

/// Rank of the calling process in MPI_COMM_WORLD (0 without MPI).
int mpi_rank();
/// Number of processes in MPI_COMM_WORLD (1 without MPI).
int mpi_size();

/// Sum over all ranks (collective).
double sum_all(double local);
/// Sum over all ranks (collective), exact in 64-bit integers.
Index sum_all(Index local);
/// Maximum over all ranks (collective).
double max_all(double local);
/// Minimum over all ranks (collective).
double min_all(double local);
/// Replaces values[0, count) on every rank by their sums over all ranks (collective; every
/// rank passes the same count). All ranks receive the same sums, bit for bit, so ranks that
/// branch on them stay in step.
void sum_all(double* values, Index count);
/// The same in single precision (the sums of single-precision factors' substitutions).
void sum_all(float* values, Index count);
/// Blocks until every rank has arrived (collective).
void barrier();

/// Concatenation of every rank's `local` in rank order, returned on every rank (collective;
/// ranks may contribute different lengths, including zero).
std::vector<double> gather_all(const std::vector<double>& local);

/// Replaces `text` on every rank by its value on `root` (collective).
void broadcast(std::string& text, int root);

} // namespace bipot
