#include "apps/pile_pullout/pile_input.hpp"

#include "fem/core/error.hpp"
#include "fem/input/detail/sections.hpp"
#include "fem/input/detail/yaml_map.hpp"
#include "fem/input/stage_schema.hpp"
#include "fem/linalg/linear_solver.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

namespace bipot::pile {

using input::Diagnostics;
using input::YamlMap;

ParamSchemaOf<Geometry> geometry_schema() {
  using G = Geometry;
  ParamSchemaOf<G> s("geometry", "pile and soil domain (axisymmetric, ground surface at z = 0)");
  s.real("pile_diameter", &G::pile_diameter, "m", "pile diameter D").positive();
  s.real("pile_length", &G::pile_length, "m", "embedded pile length L (head at the ground surface)")
      .positive();
  s.real("soil_radius", &G::soil_radius, "m", "radius of the soil domain, from the pile axis")
      .positive();
  s.real("soil_depth", &G::soil_depth, "m",
         "depth of the soil domain below the surface (> pile_length)")
      .positive();
  s.rule("soil_radius", "soil_radius > pile_diameter / 2",
         [](const G& g) -> std::optional<std::string> {
           if (g.soil_radius > 0.5 * g.pile_diameter) return std::nullopt;
           return "the soil domain (radius " + format_value(g.soil_radius) +
                  " m) must extend beyond the pile radius (" + format_value(0.5 * g.pile_diameter) +
                  " m)";
         },
         {"soil_radius", "pile_diameter"});
  s.rule("soil_depth", "soil_depth > pile_length",
         [](const G& g) -> std::optional<std::string> {
           if (g.soil_depth > g.pile_length) return std::nullopt;
           return "the soil domain (depth " + format_value(g.soil_depth) +
                  " m) must extend below the pile toe (pile_length " + format_value(g.pile_length) +
                  " m)";
         },
         {"soil_depth", "pile_length"});
  return s;
}

ParamSchemaOf<MeshDensity> mesh_schema() {
  using M = MeshDensity;
  ParamSchemaOf<M> s("mesh", "structured mesh of four blocks: pile, soil beside it, soil below "
                             "the toe (r < D/2 and r > D/2)");
  s.string("cell", &M::cell, "element type (the seed used 3-node triangles)")
      .one_of({"tri3", "tri6", "quad4", "quad8"})
      .defaulted();
  s.integer("pile_radial_cells", &M::pile_radial_cells, "cells across the pile radius")
      .at_least(1)
      .defaulted();
  s.integer("shaft_cells", &M::shaft_cells, "cells along the shaft").at_least(2).defaulted();
  s.real("shaft_growth", &M::shaft_growth, "",
         "size ratio of consecutive cells along the shaft going down "
         "(< 1 refines toward the toe)")
      .positive()
      .defaulted();
  s.integer("soil_radial_cells", &M::soil_radial_cells, "cells from the shaft to soil_radius")
      .at_least(1)
      .defaulted();
  s.real("radial_growth", &M::radial_growth, "",
         "size ratio of consecutive soil cells going away from the shaft")
      .positive()
      .defaulted();
  s.integer("below_toe_cells", &M::below_toe_cells, "cells from the toe to the bottom")
      .at_least(1)
      .defaulted();
  s.real("below_toe_growth", &M::below_toe_growth, "",
         "size ratio of consecutive cells going down from the toe")
      .positive()
      .defaulted();
  return s;
}

ParamSchemaOf<GeostaticStage> geostatic_schema() {
  ParamSchemaOf<GeostaticStage> s("stages.geostatic",
                                  "initial stress sigma_v = gamma z, sigma_h = K0 sigma_v "
                                  "(soil unit weight from materials.soil), then equilibrium "
                                  "and a displacement reset keeping stresses and contact forces");
  s.real("K0", &GeostaticStage::K0, "",
         "coefficient of earth pressure at rest (normally consolidated: 1 - sin phi')")
      .non_negative();
  return s;
}

ParamSchemaOf<InstallationStage> installation_schema() {
  using I = InstallationStage;
  ParamSchemaOf<I> s("stages.installation",
                     "prescribed radial expansion of the shaft relative to the "
                     "soil (an interference), which raises the normal stress");
  s.real("radial_displacement", &I::radial_displacement, "m",
         "radial displacement of the shaft into the soil")
      .non_negative();
  s.integer("increments", &I::increments, "load increments of the stage").at_least(1).defaulted();
  return s;
}

ParamSchemaOf<PulloutStage> pullout_schema() {
  using P = PulloutStage;
  ParamSchemaOf<P> s("stages.pullout", "upward displacement of the pile head, in equal "
                                       "increments or traced through the snap-back (control)");
  s.real("head_displacement", &P::head_displacement, "m", "head displacement reached at the end")
      .positive();
  s.integer("increments", &P::increments, "load increments of the stage").at_least(1);
  // The keys the general input's stages have too, with their texts (fem/input/stage_schema.hpp).
  add_duration_key(s, &P::duration);
  add_control_type_key(s, "control", &P::control);
  add_dissipation_step_key(s, &P::dissipation_step); // empty: derived by the analysis
  add_max_increments_key(s, &P::max_increments);
  add_energy_tolerance_key(s, &P::energy_tolerance);
  return s;
}

namespace {

const std::vector<std::string>& top_keys() {
  static const std::vector<std::string> keys = {
      "name",      "geometry",      "mesh",           "materials", "rigid_soil",
      "interface", "linear_solver", "contact_solver", "stages",    "output"};
  return keys;
}

ParameterSet read_section(const YamlMap& parent, const std::string& key, const ParamSchema& schema,
                          bool required, const std::string& doc) {
  ParameterSet p;
  if (parent.has(key)) return input::read_parameters(parent, key, schema, {});
  if (required)
    parent.missing(key, doc);
  else
    validate(schema, p); // defaults
  return p;
}

// The section's struct; left default when a required key is missing or invalid (reported
// already: parse() throws before the struct is used).
template <class P> P to_struct(const ParamSchemaOf<P>& schema, const ParameterSet& p) {
  for (const auto& spec : schema.specs())
    if (spec.required && !p.has(spec.name)) return P{};
  return *schema.fill(p);
}

template <class P>
P read_struct(const YamlMap& parent, const std::string& key, const ParamSchemaOf<P>& schema,
              bool required, const std::string& doc) {
  return to_struct(schema, read_section(parent, key, schema, required, doc));
}

void read_materials(const YamlMap& top, const SchemaIndex& materials, PileSpec& spec) {
  if (!top.has("materials")) {
    top.missing("materials", "pile: {...} and soil: {...}");
    return;
  }
  const auto mats = input::read_materials(top, materials);
  bool have_pile = false, have_soil = false;
  for (const auto& m : mats) {
    if (m.region == "pile")
      spec.pile = m, have_pile = true;
    else if (m.region == "soil")
      spec.soil = m, have_soil = true;
    else
      top.diag().error_at(m.where, "the pile model has two materials, 'pile' and 'soil'");
  }
  YamlMap m(top.node("materials"), "materials", top.diag(), {"pile", "soil"});
  if (!have_pile && m.valid() && !m.has("pile")) m.missing("pile", "the pile's material");
  if (!have_soil && m.valid() && !m.has("soil")) m.missing("soil", "the soil's material");
}

void read_interface(const YamlMap& top, const SchemaIndex& laws, PileSpec& spec) {
  if (!top.has("interface")) {
    top.missing("interface", "law: rccm | coulomb_signorini | perfect_bonding, and its "
                             "parameters");
    return;
  }
  YamlMap m(top.node("interface"), "interface", top.diag(), {"law", "parameters"});
  if (!m.valid()) return;
  spec.interface_where = top.where("interface");
  if (!m.string("law", spec.law, true) || spec.law.empty()) return;
  if (!laws.contains(spec.law)) {
    m.error("law", laws.unknown_message(spec.law));
    return;
  }
  if (m.has("parameters"))
    spec.law_parameters = input::read_parameters(m, "parameters", laws.schema(spec.law), {});
  else {
    const auto problems = validate(laws.schema(spec.law), spec.law_parameters);
    for (const auto& p : problems)
      m.error("parameters", p.key + ": " + p.message);
  }
}

void read_stages(const YamlMap& top, PileSpec& spec) {
  if (!top.has("stages")) {
    top.missing("stages", "geostatic, installation and pullout");
    return;
  }
  YamlMap m(top.node("stages"), "stages", top.diag(), {"geostatic", "installation", "pullout"});
  if (!m.valid()) return;
  spec.geostatic = read_struct(m, "geostatic", geostatic_schema(), true, "K0");
  spec.installation = read_struct(m, "installation", installation_schema(), true,
                                  "radial_displacement, increments");
  spec.pullout = read_struct(m, "pullout", pullout_schema(), true, "head_displacement, increments");
  spec.geostatic_where = m.where("geostatic");
  spec.installation_where = m.where("installation");
  spec.pullout_where = m.where("pullout");
}

void read_output(const YamlMap& top, PileSpec& spec) {
  spec.output.directory = "results/pile_pullout";
  if (!top.has("output")) return;
  YamlMap m(top.node("output"), "output", top.diag(),
            {"directory", "vtk", "every", "profiles_at", "checkpoint"});
  if (!m.valid()) return;
  if (m.string("directory", spec.output.directory)) spec.output.where = m.where("directory");
  m.boolean("vtk", spec.output.vtk);
  if (m.integer("every", spec.output.every) && spec.output.every < 1)
    m.error("every", "value " + std::to_string(spec.output.every) + " is out of range [1, inf)");
  if (m.reals("profiles_at", spec.profiles_at_mm) && m.has("profiles_at")) {
    if (!std::is_sorted(spec.profiles_at_mm.begin(), spec.profiles_at_mm.end()) ||
        std::any_of(spec.profiles_at_mm.begin(), spec.profiles_at_mm.end(),
                    [](double v) { return !(v > 0); }))
      m.error("profiles_at", "expected increasing head displacements > 0 (mm)");
  }
  // As in bipot input files; the stage names are geostatic, installation and pullout
  // (checked with the stages by make_problem).
  input::read_checkpoint(m, spec.output);
}

PileSpec parse(const std::string& text, const std::string& file_name,
               const InputCatalogue& catalogue) {
  Diagnostics diag(file_name);
  const YAML::Node root = input::load_yaml(text, file_name);
  PileSpec spec;
  spec.file = file_name;
  YamlMap top(root, "", diag, top_keys());
  if (!top.valid()) throw InputError(diag.problems());
  top.string("name", spec.name);
  const auto geometry = geometry_schema();
  const ParameterSet g = read_section(top, "geometry", geometry, true,
                                      "pile_diameter, pile_length, soil_radius, soil_depth");
  spec.geometry = to_struct(geometry, g);
  spec.mesh = read_struct(top, "mesh", mesh_schema(), false, "");
  read_materials(top, catalogue.materials, spec);
  top.boolean("rigid_soil", spec.rigid_soil);
  read_interface(top, catalogue.interface_laws, spec);
  spec.linear_solver = read_section(top, "linear_solver", LinearSolver::schema(), false, "");
  if (top.has("contact_solver"))
    spec.contact_solver = input::read_contact_solver(top, catalogue.contact_solvers);
  else
    validate(catalogue.contact_solvers.schema(spec.contact_solver.type),
             spec.contact_solver.parameters);
  read_stages(top, spec);
  read_output(top, spec);
  if (spec.name.empty()) spec.name = spec.law;
  if (!diag.problems().empty()) throw InputError(diag.problems());
  return spec;
}

} // namespace

PileSpec read_pile_file(const std::string& path, const InputCatalogue& catalogue) {
  return parse(input::read_text_file(path), path, catalogue);
}

PileSpec read_pile_text(const std::string& text, const std::string& file_name,
                        const InputCatalogue& catalogue) {
  return parse(text, file_name, catalogue);
}

std::string describe_pile_input(bool markdown) {
  std::ostringstream os;
  os << (markdown ? "" : "pile_pullout input file (YAML), top-level keys:\n");
  if (!markdown)
    os << "  name: label of the run in plots (default: the interface law)\n"
          "  geometry, mesh: see below\n"
          "  materials: {pile: {type: <material>, ...}, soil: {type: <material>, ...}}\n"
          "  rigid_soil: true fixes every soil node (verification; default false)\n"
          "  interface: {law: rccm | coulomb_signorini | perfect_bonding, parameters: {...}}\n"
          "  linear_solver, contact_solver: as in bipot input files (bipot describe NAME)\n"
          "  stages: {geostatic: {...}, installation: {...}, pullout: {...}}, see below\n"
          "  output: {directory, vtk, every, profiles_at: [head displacements, mm],\n"
          "           checkpoint: {after: [stages], steps: [{stage, step}], every: n}}\n"
          "          (stages geostatic, installation, pullout; see `bipot describe input`)\n\n";
  const std::vector<ParamSchema> schemas = {geometry_schema(), mesh_schema(), geostatic_schema(),
                                            installation_schema(), pullout_schema()};
  for (const ParamSchema& s : schemas)
    os << (markdown ? "### `" + s.name() + "`\n\n" + s.doc() + "\n\n" + s.markdown_table() + "\n"
                    : s.describe() + "\n");
  return os.str();
}

} // namespace bipot::pile
