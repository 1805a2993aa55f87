#pragma once
/// The validated content of a bipot input file, as plain data (no yaml-cpp types).
/// Every item that names something only checkable against the mesh (sets, regions) keeps
/// `where` = "file:line:col: key.path" so later checks report the user's line.

#include "fem/core/parameter_schema.hpp"
#include "fem/mesh/structured_mesh.hpp"

#include <optional>
#include <string>
#include <vector>

namespace bipot {

/// A node set made of the nodes inside a box (bounds inclusive, up to a small tolerance).
struct BoxSetSpec {
  std::string name;
  std::vector<double> min, max; ///< one value per spatial component
  /// If not empty, only the nodes of this region's cells: after an interface split, the
  /// copies on one side (e.g. the pile's shaft nodes, not the soil's).
  std::string region;
  std::string where;
};

struct MeshSpec {
  std::string file; ///< Gmsh .msh path, resolved against the input file's folder; or
  bool has_blocks = false;
  std::string cell = "quad4";
  /// Triangle split of the blocks' quads: right, left, alternating or crossed (tri3 only).
  std::string diagonals = "right";
  AxisSegments x, y, z;
  std::vector<std::string> block_regions;
  std::vector<BoxSetSpec> box_sets; ///< extra node sets: `sets: {name: {min, max}}`
  std::string where;
};

struct MaterialSpec {
  std::string region;
  std::string type;
  ParameterSet parameters; ///< validated against the material's schema, defaults filled in
  std::string where;
};

/// Initial (e.g. geostatic) stress in a region; tension positive.
struct InitialStressSpec {
  std::string region;
  std::string type;               ///< "geostatic" or "constant"
  double unit_weight = 0;         ///< kN/m³ (geostatic)
  double lateral_coefficient = 1; ///< K0 (geostatic): horizontal = K0 × vertical
  double surface = 0;             ///< vertical coordinate of the free surface (geostatic)
  std::vector<double> stress;     ///< Voigt components (constant)
  std::string where;
};

struct DirichletSpec {
  std::string set;
  int component = 0; ///< 0 = x/r, 1 = y/z(axisymmetric), 2 = z
  double value = 0;  ///< value reached at the end of the stage (m)
  std::string where;
};

struct LoadSpec {
  enum class Type { Pressure, Traction, Gravity };
  Type type = Type::Pressure;
  std::string set;              ///< facet set (pressure, traction)
  double pressure = 0;          ///< kPa, acts against the outward normal
  std::vector<double> traction; ///< kPa, one per spatial component
  std::string where;
};

/// Extra normal offset of an interface's pairs reached at the end of a stage (ramped like a
/// boundary condition): > 0 opens, < 0 prescribes an interference (installation of a pile).
struct InterfaceGapSpec {
  std::string interface;
  double value = 0; ///< m
  std::string where;
};

/// The displacement of an interface's rigid obstacle reached at the end of a stage (ramped
/// like a boundary condition from its value at the end of the previous stage; an obstacle a
/// stage does not name keeps its displacement).
struct ObstacleDisplacementSpec {
  std::string interface;
  std::vector<double> value; ///< m, one per spatial component
  std::string where;
};

/// A condition on a rigid body's reference node in a stage: a prescribed displacement or
/// rotation (`value`, reached at the end of the stage and ramped like a boundary condition),
/// or a force or moment (`force`, ramped like a load). A component not named is free.
struct RigidBodyConditionSpec {
  std::string body;
  /// Translations 0..d−1, then rotations (plane strain: 2 = rz; 3D: 3, 4, 5 = rx, ry, rz);
  /// axisymmetric: 1 (z) only.
  int component = 0;
  double value = 0; ///< m or rad; kN or kN·m for a force (per unit thickness in plane strain)
  bool force = false;
  std::string where;
};

/// How a stage advances its load factor λ (0 → 1 over the stage): `ramp` (default) in the
/// planned increments; `arc_length` (Crisfield, cylindrical: the interface displacements move
/// by a given length each step, λ follows and may decrease); `dissipation` (ramp while the
/// interfaces do not dissipate, then each step dissipates `dissipation_step`; Gutiérrez 2004):
/// both trace snap-backs that a ramp jumps over.
struct ControlSpec {
  std::string type = "ramp";
  std::optional<double> arc_length;       ///< first arc length (m); empty: the first increment's
  std::optional<double> dissipation_step; ///< kJ per step; empty: adhesion energy / increments
  std::optional<int> max_increments;      ///< path-following steps allowed; empty: 20 × increments
  std::string where;
  bool path_following() const { return type != "ramp"; }
};

/// A stage's change of an interface's law or parameters (`interfaces: {name: {law, parameters}}`
/// in the stage), resolved when read: `law` and `parameters` are the complete set in force
/// from this stage on (parameters given without a new law are merged over those in force).
struct InterfaceLawChangeSpec {
  std::string interface;
  std::string law;
  ParameterSet parameters; ///< validated against the law's schema, defaults filled in
  std::string where;
};

/// A stage lists the boundary conditions and loads in force at its end; values are ramped
/// linearly over its increments from their state at the end of the previous stage.
struct StageSpec {
  std::string name;
  int increments = 1;
  double duration = 1.0;            ///< pseudo-time (s) spanned by the stage
  bool reset_displacements = false; ///< zero the displacements at the end, keep stresses
  std::vector<DirichletSpec> boundary_conditions;
  std::vector<LoadSpec> loads;
  std::vector<InterfaceGapSpec> interface_gaps;
  std::vector<ObstacleDisplacementSpec> obstacle_displacements;
  std::vector<RigidBodyConditionSpec> rigid_body_conditions;
  std::vector<InterfaceLawChangeSpec> interface_laws;
  ControlSpec control;
  /// Load factors in (0, 1], increasing, at which the ramp also ends an increment and the
  /// results (VTK included) are written, besides the planned levels k/increments.
  std::vector<double> output_at;
  /// The run's |energy balance error| allowed after every increment, relative to the work
  /// put in (0: no control; add_energy_tolerance_key()). On by default: issue 11 asks every
  /// run to keep its balance to 1e-6; runs at round-off never halve for it.
  double energy_tolerance = 1e-6;
  std::string where;
};

/// An interface between two bodies: `between: [a, b]` regions (a = body 1) of a conforming
/// mesh, or `facet_sets: [a, b]` with coincident nodes or nodes facing each other.
/// A rigid analytical surface as an interface's body 2 (validated: a known type, the
/// vectors of the kinematics' size, a non-zero normal or axis, normalised, a radius > 0).
struct ObstacleSpec {
  std::string type; ///< "plane" (or "line"), "circle", "sphere", "cylinder"
  std::vector<double>
      point; ///< plane: a point on it; circle, sphere: centre; cylinder: on the axis
  std::vector<double> normal; ///< plane: unit normal pointing out of the obstacle
  std::vector<double> axis;   ///< cylinder: unit axis
  double radius = 0;          ///< m
  std::string where;
};

struct InterfaceSpec {
  std::string name;
  std::vector<std::string> between;    ///< two region names, or empty
  std::vector<std::string> facet_sets; ///< two facet set names, or empty
  std::string law;
  ParameterSet parameters; ///< validated against the law's schema
  double initial_gap = 0;  ///< m
  /// facet_sets only: "coincident" (same positions) or "normal" (node of b on the normal line
  /// of the node of a; their distance is the pair's initial gap)
  std::string pairing = "coincident";
  /// `facet_sets: [a]` with an obstacle: body 2 is this rigid surface.
  std::optional<ObstacleSpec> obstacle;
  std::string where;
};

/// A rigid body: the nodes of a region's cells (or of a node or facet set) move with a
/// reference node at `reference_point` (default: the nodes' centroid).
struct RigidBodySpec {
  std::string name;
  std::string region, set; ///< exactly one given
  std::vector<double> reference_point;
  std::string where;
};

struct ContactSolverSpec {
  std::string type = "generalized_newton";
  ParameterSet parameters; ///< validated against the solver's schema
  std::string where;
};

struct OutputSpec {
  std::string directory = "results";
  bool vtk = true;
  int every = 1; ///< write VTK every n-th converged increment (and always the last of a stage)
  /// "file:line:col: output.directory" when the input gives it, "" otherwise
  std::string where;
  /// `checkpoint: {after: [stage names]}`: write `checkpoint_<stage>.bin` into the results at
  /// the end of these stages (the complete state, for `bipot run --restart`).
  std::vector<std::string> checkpoint_after;
  std::string checkpoint_where;
  /// `checkpoint: {steps: [{stage, step}]}`: write `checkpoint_<stage>_step<k>.bin` when the
  /// stage reaches its planned load level k/increments (checkpoint_section.cpp).
  struct CheckpointStep {
    std::string stage;
    int step = 0;
    std::string where, step_where; ///< of its `stage` and `step` keys
  };
  std::vector<CheckpointStep> checkpoint_steps;
  /// `checkpoint: {every: n}`: also at the planned levels n, 2n, … of every ramp stage; 0: not.
  int checkpoint_every = 0;
  /// A checkpoint within `stage` at its planned level `k` is asked for (never within a
  /// path-following stage: `every` skips those, `steps` naming one is refused at `check`).
  bool checkpoint_at(const StageSpec& stage, int k) const {
    if (k < 1 || stage.control.path_following()) return false;
    if (checkpoint_every > 0 && k % checkpoint_every == 0) return true;
    for (const auto& c : checkpoint_steps)
      if (c.stage == stage.name && c.step == k) return true;
    return false;
  }
};

struct ProblemSpec {
  std::string file; ///< the input file as given
  std::string kinematics = "plane_strain";
  MeshSpec mesh;
  std::vector<MaterialSpec> materials;
  ParameterSet linear_solver; ///< validated against LinearSolver's schema
  std::vector<InitialStressSpec> initial_stress;
  std::vector<InterfaceSpec> interfaces;
  std::vector<RigidBodySpec> rigid_bodies;
  ContactSolverSpec contact_solver;
  std::vector<StageSpec> stages;
  OutputSpec output;
};

} // namespace bipot
