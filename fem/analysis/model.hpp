#pragma once
/// A problem ready to solve: the validated input, its mesh, its materials and its interfaces.

#include "fem/analysis/interface_module.hpp"
#include "fem/assembly/rigid_body_constraint.hpp"
#include "fem/core/material.hpp"
#include "fem/core/nonlinear_solver_options.hpp"
#include "fem/core/registry.hpp"
#include "fem/element/kinematics.hpp"
#include "fem/input/problem_spec.hpp"
#include "fem/mesh/interface_mesh.hpp"
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
  std::vector<InterfaceMesh> interfaces;            ///< split and paired, in input order
  /// The nonlinear solver of `contact_solver:` (its driver-side options).
  NonlinearSolverOptions contact_solver;
  /// In input order; their reference nodes are the mesh's last nodes (two per body).
  std::vector<RigidBody> rigid_bodies;
  /// Builds and enforces the interfaces (null for a model built without one: no interfaces).
  std::shared_ptr<const InterfaceModule> interface_module;
  /// What the interface module keeps of the model: the interface laws in force per stage,
  /// the full solver options.
  std::shared_ptr<const InterfaceData> interface_data;
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
/// r ≥ 0. Then `interfaces` splits the mesh along each interface and builds their laws and
/// the solver options (InterfaceModule::build). Materials come from `materials`, which must
/// know every name `spec` uses. Throws InputError listing every problem with the user's
/// file:line:col. (apps/catalogue: build_model(spec, catalogue) with bipot's catalogue.)
Model build_model(const ProblemSpec& spec, const Registry<Material>& materials,
                  std::shared_ptr<const InterfaceModule> interfaces);

/// The mesh described by a MeshSpec (no checks against the rest of the input).
Mesh build_mesh(const MeshSpec& spec, int dim);

} // namespace bipot
