#pragma once
/// The pile pull-out input file: geometry, mesh density, materials, the interface law, the
/// solvers and the three stages (geostatic, installation, pull-out). Read and validated in
/// one pass with the toolkit's readers, so problems come as "file:line:col: key: message".

#include "fem/core/parameter_binding.hpp"
#include "fem/input/input_catalogue.hpp"
#include "fem/input/problem_spec.hpp"

#include <optional>
#include <string>
#include <vector>

namespace bipot::pile {

/// The `geometry:` section (geometry_schema()).
struct Geometry {
  double pile_diameter = 0, pile_length = 0, soil_radius = 0, soil_depth = 0; ///< m
};
/// The `mesh:` section (mesh_schema()): cells and grading of the four blocks.
struct MeshDensity {
  std::string cell = "tri3";
  int pile_radial_cells = 3, shaft_cells = 52, soil_radial_cells = 30, below_toe_cells = 20;
  double shaft_growth = 1.0, radial_growth = 1.15, below_toe_growth = 1.15;
};
/// `stages.geostatic` (geostatic_schema()).
struct GeostaticStage {
  double K0 = 0;
};
/// `stages.installation` (installation_schema()).
struct InstallationStage {
  double radial_displacement = 0; ///< m
  int increments = 4;
};
/// `stages.pullout` (pullout_schema()).
struct PulloutStage {
  double head_displacement = 0; ///< m
  int increments = 0;
  double duration = 1.0; ///< s
  std::string control = "ramp";
  std::optional<double> dissipation_step = std::nullopt; ///< kJ; empty: derived by the analysis
  std::optional<int> max_increments = std::nullopt;      ///< empty: derived by the analysis
  double energy_tolerance = 1e-6; ///< StageSpec::energy_tolerance (0: no control)
};

struct PileSpec {
  std::string file;
  std::string name; ///< label of the run in plots (default: the law's name)
  Geometry geometry;
  MeshDensity mesh;
  MaterialSpec pile, soil;
  bool rigid_soil = false; ///< every soil node fixed (verification runs)
  std::string law;
  ParameterSet law_parameters;
  std::string interface_where;
  ParameterSet linear_solver;
  ContactSolverSpec contact_solver;
  GeostaticStage geostatic;
  InstallationStage installation;
  PulloutStage pullout;
  std::string geostatic_where, installation_where, pullout_where;
  OutputSpec output;
  std::vector<double> profiles_at_mm; ///< head displacements (mm) of the shaft profiles
};

ParamSchemaOf<Geometry> geometry_schema();
ParamSchemaOf<MeshDensity> mesh_schema();
ParamSchemaOf<GeostaticStage> geostatic_schema();
ParamSchemaOf<InstallationStage> installation_schema();
ParamSchemaOf<PulloutStage> pullout_schema();

/// Reads and validates a pile input file against `catalogue` (the soil and pile materials,
/// the law and the contact solver); throws InputError listing every problem.
PileSpec read_pile_file(const std::string& path, const InputCatalogue& catalogue);
/// Same from text (tests); `file_name` is used in messages.
PileSpec read_pile_text(const std::string& text, const std::string& file_name,
                        const InputCatalogue& catalogue);

/// The file's sections and their parameters, as Markdown (docs) or plain text (--help).
std::string describe_pile_input(bool markdown);

} // namespace bipot::pile
