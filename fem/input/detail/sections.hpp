#pragma once
/// Internal to fem/input: readers for each section of the input file. Each records its
/// problems in the map's Diagnostics and returns what it could read.

#include "fem/core/parameter_schema.hpp"
#include "fem/input/detail/yaml_map.hpp"
#include "fem/input/input_catalogue.hpp"
#include "fem/input/problem_spec.hpp"

namespace bipot::input {

MeshSpec read_mesh(const YamlMap& top, int dim, const std::string& base_dir);
std::vector<MaterialSpec> read_materials(const YamlMap& top, const SchemaIndex& materials);
std::vector<InitialStressSpec> read_initial_stress(const YamlMap& top, int dim);
/// The displacement components of a kinematics by index ("x", "y" / "r", "z" / "x", "y", "z").
const std::vector<std::string>& component_names(const std::string& kinematics);

std::vector<StageSpec> read_stages(const YamlMap& top, const std::string& kinematics,
                                   const std::vector<InterfaceSpec>& interfaces,
                                   const SchemaIndex& laws);
/// A stage's `interfaces:` map (law or parameter changes); `active` holds each interface's
/// law and parameters in force before the stage and is updated.
void read_stage_interfaces(const YamlMap& stage, const std::vector<InterfaceSpec>& interfaces,
                           const SchemaIndex& laws, std::vector<InterfaceLawChangeSpec>& active,
                           StageSpec& st);
/// Cross-section rules of path-following stages (need the contact solver and interfaces).
void check_stage_controls(const ProblemSpec& spec, Diagnostics& diag);
OutputSpec read_output(const YamlMap& top);
/// `output.checkpoint` (checkpoint_section.cpp), read from the `output` map into `out`, and
/// its checks against the stages: names that exist, steps within a stage's increments, no
/// step within a path-following stage.
void read_checkpoint(const YamlMap& output, OutputSpec& out);
void check_checkpoints(const ProblemSpec& spec, Diagnostics& diag);
std::vector<InterfaceSpec> read_interfaces(const YamlMap& top, const std::string& kinematics,
                                           const SchemaIndex& laws);
/// An interface with `obstacle` (obstacle_section.cpp): the obstacle, and the one facet set
/// of the body it needs (no `between`, no `pairing`).
void read_obstacle_interface(const YamlMap& m, const std::string& kinematics, InterfaceSpec& spec);
/// The `rigid_bodies` section and a stage's `rigid_bodies` conditions
/// (rigid_body_section.cpp).
std::vector<RigidBodySpec> read_rigid_bodies(const YamlMap& top, int dim);
void read_stage_rigid_bodies(const YamlMap& stage, const std::string& kinematics, StageSpec& st);
/// A stage's `obstacle_displacements` (obstacle_section.cpp).
void read_obstacle_displacements(const YamlMap& stage, int dim, StageSpec& st);
ContactSolverSpec read_contact_solver(const YamlMap& top, const SchemaIndex& solvers);

/// Reads the map at `parent[key]` as parameters of `schema` (keys in `skip` are left to the
/// caller), decoding each value by its declared type, validating ranges, filling defaults,
/// and reporting each problem at its own line.
ParameterSet read_parameters(const YamlMap& parent, const std::string& key,
                             const ParamSchema& schema, const std::vector<std::string>& skip);

/// The keys of `schema` in the map `m`, which holds other keys too (read by their own readers,
/// and checked against the map's allowed keys by YamlMap): read as read_parameters() does.
ParameterSet read_schema_keys(const YamlMap& m, const ParamSchema& schema);

/// Same for a map node already in hand; the keys it gives are set over `base` if not null.
ParameterSet read_parameters_node(const YAML::Node& node, const std::string& path,
                                  Diagnostics& diag, const ParamSchema& schema,
                                  const std::vector<std::string>& skip,
                                  const ParameterSet* base = nullptr);

} // namespace bipot::input
