#pragma once
/// The pile pull-out input file: geometry, mesh density, materials, the interface law, the
/// solvers and the three stages (geostatic, installation, pull-out). Read and validated in
/// one pass with the toolkit's readers, so problems come as "file:line:col: key: message".

#include "fem/core/parameter_schema.hpp"
#include "fem/input/input_catalogue.hpp"
#include "fem/input/problem_spec.hpp"

#include <string>
#include <vector>

namespace bipot::pile {

struct PileSpec {
  std::string file;
  std::string name;      ///< label of the run in plots (default: the law's name)
  ParameterSet geometry; ///< geometry_schema()
  ParameterSet mesh;     ///< mesh_schema()
  MaterialSpec pile, soil;
  bool rigid_soil = false; ///< every soil node fixed (verification runs)
  std::string law;
  ParameterSet law_parameters;
  std::string interface_where;
  ParameterSet linear_solver;
  ContactSolverSpec contact_solver;
  ParameterSet geostatic, installation, pullout; ///< the stage schemas below
  std::string geostatic_where, installation_where, pullout_where;
  OutputSpec output;
  std::vector<double> profiles_at_mm; ///< head displacements (mm) of the shaft profiles
};

ParamSchema geometry_schema();
ParamSchema mesh_schema();
ParamSchema geostatic_schema();
ParamSchema installation_schema();
ParamSchema pullout_schema();

/// Reads and validates a pile input file against `catalogue` (the soil and pile materials,
/// the law and the contact solver); throws InputError listing every problem.
PileSpec read_pile_file(const std::string& path, const InputCatalogue& catalogue);
/// Same from text (tests); `file_name` is used in messages.
PileSpec read_pile_text(const std::string& text, const std::string& file_name,
                        const InputCatalogue& catalogue);

/// The file's sections and their parameters, as Markdown (docs) or plain text (--help).
std::string describe_pile_input(bool markdown);

} // namespace bipot::pile
