#pragma once
/// Weights and local frames of the node pairs of an interface (docs/formulation.md §5, §6).

#include "contact/interface/interface_mesh.hpp"
#include "fem/element/kinematics.hpp"
#include "fem/mesh/mesh.hpp"

#include <Eigen/Core>

#include <string>

namespace bipot::contact {

/// Sets weight, normal, tangent1 and tangent2 of every pair of `iface` from iface.facets_a
/// (outward of body 1), whose nodes must all be the node_a of some pair:
///   A_i = Σ_facets Σ_q N_i(ξ_q) JxW_q        (JxW includes 2π r in axisymmetry),
///   n_i = Σ_facets Σ_q N_i(ξ_q) JxW_q n_q, normalised,
/// with a Gauss rule of degree 2p + 1 for facets of order p (exact for straight lines and planar
/// faces). Where that sum vanishes (a node on the axis in axisymmetry with A_i = 0) the plain
/// average of the adjacent facets' unit normals is used instead. Tangents: complete_frame().
/// Throws bipot::InputError, prefixed by `context`, for a pair that no facet touches or whose
/// facets' normals cancel; bipot::Error for a facet node that is no pair's node_a.
void compute_pair_geometry(const Mesh& mesh, Kinematics kin, Interface& iface,
                           const std::string& context = "");

/// The pair's local frame as a 3 × 3 matrix with columns [n, t1, t2] (t2 zero in 2D): a
/// local vector v has global components Q v.
Eigen::Matrix3d pair_frame(const InterfacePair& p, int dim);

} // namespace bipot::contact
