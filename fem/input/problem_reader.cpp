#include "fem/input/problem_reader.hpp"

#include "fem/core/error.hpp"
#include "fem/core/nearest_name.hpp"
#include "fem/input/detail/sections.hpp"
#include "fem/input/detail/yaml_map.hpp"
#include "fem/linalg/linear_solver.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace bipot {

using input::Diagnostics;
using input::YamlMap;

namespace {

const std::vector<std::pair<std::string, std::string>>& top_level_keys() {
  static const std::vector<std::pair<std::string, std::string>> keys = {
      {"kinematics", "plane_strain | axisymmetric | three_d (default plane_strain)"},
      {"mesh", "either file: a Gmsh .msh, or blocks: a structured blocked mesh"},
      {"materials", "map region name -> {type: <material>, <its parameters>}"},
      {"linear_solver", "method, preconditioner, tolerance, ... (bipot describe linear_solver)"},
      {"initial_stress", "list of {region, type: geostatic|constant, ...}"},
      {"interfaces", "list of {name, between: [body1, body2] | facet_sets: [a, b], law, "
                     "parameters, initial_gap}"},
      {"rigid_bodies", "list of {name, region | set, reference_point}"},
      {"contact_solver", "type: semismooth_newton | bipotential_uzawa, and its options"},
      {"stages", "list of load stages: name, increments, boundary_conditions, loads, "
                 "interface_gaps, interfaces (law changes), control"},
      {"output", "directory, vtk, every, checkpoint"},
  };
  return keys;
}

ProblemSpec read_root(const YAML::Node& root, Diagnostics& diag, const std::string& base_dir,
                      const InputCatalogue& catalogue) {
  ProblemSpec spec;
  spec.file = diag.file();
  std::vector<std::string> keys;
  for (const auto& kv : top_level_keys())
    keys.push_back(kv.first);
  YamlMap top(root, "", diag, keys);
  if (!top.valid()) return spec;

  if (top.string("kinematics", spec.kinematics)) {
    const std::vector<std::string> allowed = {"plane_strain", "axisymmetric", "three_d"};
    if (std::find(allowed.begin(), allowed.end(), spec.kinematics) == allowed.end())
      top.error("kinematics", "unknown kinematics '" + spec.kinematics +
                                  "'; allowed: plane_strain, axisymmetric, three_d");
  }
  const int dim = spec.kinematics == "three_d" ? 3 : 2;

  if (top.has("mesh"))
    spec.mesh = input::read_mesh(top, dim, base_dir);
  else
    top.missing("mesh", "a Gmsh file or a blocks generator");

  if (top.has("materials"))
    spec.materials = input::read_materials(top, catalogue.materials);
  else
    top.missing("materials", "one entry per mesh region");

  ParamSchema solver_schema = LinearSolver::schema();
  if (top.has("linear_solver")) {
    spec.linear_solver = input::read_parameters(top, "linear_solver", solver_schema, {});
  } else {
    validate(solver_schema, spec.linear_solver); // defaults
  }

  if (top.has("initial_stress")) spec.initial_stress = input::read_initial_stress(top, dim);
  if (top.has("interfaces"))
    spec.interfaces = input::read_interfaces(top, spec.kinematics, catalogue.interface_laws);
  if (top.has("rigid_bodies")) spec.rigid_bodies = input::read_rigid_bodies(top, dim);
  if (top.has("contact_solver"))
    spec.contact_solver = input::read_contact_solver(top, catalogue.contact_solvers);
  else
    validate(catalogue.contact_solvers.schema(spec.contact_solver.type),
             spec.contact_solver.parameters);
  if (top.has("stages"))
    spec.stages =
        input::read_stages(top, spec.kinematics, spec.interfaces, catalogue.interface_laws);
  else
    top.missing("stages", "at least one load stage");
  if (top.has("output")) spec.output = input::read_output(top);
  input::check_checkpoints(spec, diag);
  input::check_stage_controls(spec, diag);
  return spec;
}

ProblemSpec parse(const std::string& text, const std::string& file_name,
                  const std::string& base_dir, const InputCatalogue& catalogue) {
  Diagnostics diag(file_name);
  const YAML::Node root = input::load_yaml(text, file_name);
  ProblemSpec spec = read_root(root, diag, base_dir, catalogue);
  if (!diag.problems().empty()) throw InputError(diag.problems());
  return spec;
}

} // namespace

ProblemSpec read_problem_file(const std::string& path, const InputCatalogue& catalogue) {
  const auto dir = std::filesystem::path(path).parent_path().string();
  return parse(input::read_text_file(path), path, dir, catalogue);
}

ProblemSpec read_problem_text(const std::string& text, const std::string& file_name,
                              const InputCatalogue& catalogue) {
  return parse(text, file_name, "", catalogue);
}

void check_stage_controls(const ProblemSpec& spec) {
  Diagnostics diag(spec.file);
  input::check_stage_controls(spec, diag);
  input::check_checkpoints(spec, diag);
  if (!diag.problems().empty()) throw InputError(diag.problems());
}

std::string describe_input_format() {
  std::ostringstream os;
  os << "bipot input file (YAML), top-level keys:\n";
  for (const auto& [key, doc] : top_level_keys())
    os << "  " << key << ": " << doc << "\n";
  return os.str();
}

} // namespace bipot
