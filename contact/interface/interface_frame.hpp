#pragma once
/// The local frame [n, t1 (, t2)] of an interface pair and the change of components between it
/// and the global axes. Local vectors use the layout of the interface laws (contact/laws):
/// normal component first, then the tangential ones.

#include "contact/interface/interface_mesh.hpp"
#include "contact/laws/interface_law.hpp"

#include <array>

namespace bipot::contact {

/// Completes the unit normal `n` into an orthonormal frame, deterministically:
/// - dim 2: t1 = (−n_y, n_x, 0), i.e. n rotated counter-clockwise, so (n, t1) is right-handed
///   (n_x t1_y − n_y t1_x = 1); t2 = 0;
/// - dim 3: e = the global axis along which |n_i| is smallest (first one on ties),
///   t1 = (e − (e·n) n)/‖…‖, t2 = n × t1, hence t1 × t2 = n and (n, t1, t2) is right-handed.
/// `n` must have unit length (z component 0 in 2D).
void complete_frame(const std::array<double, 3>& n, int dim, std::array<double, 3>& t1,
                    std::array<double, 3>& t2);

/// Components of the global vector `global_vec` (`dim` values) in the pair's frame:
/// [n·v, t1·v (, t2·v)], a LocalVector of size `dim`.
LocalVector to_local(const InterfacePair& pair, const double* global_vec, int dim);

/// Global components (`dim` values written to `out`) of the local vector `local` (size `dim`):
/// out = l_0 n + l_1 t1 (+ l_2 t2). Inverse of to_local() since the frame is orthonormal.
void to_global(const InterfacePair& pair, const LocalVector& local, double* out, int dim);

} // namespace bipot::contact
