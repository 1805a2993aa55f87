#pragma once
/// A problem ready to solve: the validated input, its mesh and its materials.

#include "contact/interface/interface_mesh.hpp"
#include "contact/laws/interface_law.hpp"
#include "contact/solver/contact_solver_options.hpp"
#include "fem/analysis/catalogue.hpp"
#include "fem/analysis/interface_module.hpp"
#include "fem/assembly/rigid_body_constraint.hpp"
#include "fem/core/material.hpp"
#include "fem/element/kinematics.hpp"
#include "fem/input/problem_spec.hpp"
#include "fem/mesh/mesh.hpp"

#include <memory>
#include <vector>

namespace bipot {

struct Model {
  ProblemSpec spec;
  Kinematics kinematics = Kinematics::PlaneStrain;
  Mesh mesh;
  std::vector<std::unique_ptr<Material>> materials; ///< owned, one per materials entry
  std::vector<const Material*> material_of_region;  ///< indexed by mesh region id
  std::vector<contact::Interface> interfaces;       ///< split and paired, in input order
  std::vector<std::unique_ptr<contact::InterfaceLaw>> interface_laws; ///< one per interface
  /// A law a stage puts in force on an interface (stage `interfaces:`), in stage order.
  struct StageLaw {
    std::size_t stage = 0, interface = 0;
    std::unique_ptr<contact::InterfaceLaw> law;
  };
  std::vector<StageLaw> stage_laws;
  contact::ContactSolverOptions contact_solver;
  /// In input order; their reference nodes are the mesh's last nodes (two per body).
  std::vector<RigidBody> rigid_bodies;
  /// Enforces the interfaces (the catalogue's; null for a model without interfaces).
  std::shared_ptr<const InterfaceModule> interface_module;
};

/// Adds the rigid bodies of model.spec to the model (rigid_bodies.cpp): their nodes, and two
/// reference nodes per body appended to the mesh. Throws InputError, each problem at its
/// place, for an unknown region or set (with the nearest name), a body without nodes, nodes
/// of two bodies, a boundary condition on a body's node, and a stage
/// naming an unknown body.
void add_rigid_bodies(Model& model);

/// Builds the mesh (generator or Gmsh file) and the materials, then checks everything that
/// needs the mesh: every region has a material and every material a region, every set named
/// by a boundary condition or load exists (with the nearest names), axisymmetric meshes have
/// r ≥ 0. Then splits the mesh along each interface (perfect bonding in every stage keeps
/// shared nodes; an interface bonded in some stages only is split and tied on its pairs).
/// Materials, laws and the contact solver are built from `catalogue`, which must know every
/// name `spec` uses (the one `spec` was read with). Throws InputError listing every problem
/// with the user's file:line:col.
Model build_model(const ProblemSpec& spec, const Catalogue& catalogue);

/// The mesh described by a MeshSpec (no checks against the rest of the input).
Mesh build_mesh(const MeshSpec& spec, int dim);

} // namespace bipot
