#include "apps/pile_pullout/pile_problem.hpp"

#include "fem/input/problem_reader.hpp"

namespace bipot::pile {

namespace {

// Regions of the four blocks (x fastest): the soil column under the pile is its own region
// so that the toe is a separate interface (the installation interference acts on the shaft
// only, and the toe's force is reported on its own).
const char* kPile = "pile";
const char* kSoil = "soil";
const char* kSoilToe = "soil_below_toe";

AxisSegments axis(double a, double b, double c, long n1, long n2, double g1, double g2) {
  AxisSegments s;
  s.breaks = {a, b, c};
  s.cells = {static_cast<int>(n1), static_cast<int>(n2)};
  s.grading = {g1, g2};
  return s;
}

DirichletSpec bc(const std::string& set, int component, double value, const std::string& where) {
  DirichletSpec d;
  d.set = set;
  d.component = component;
  d.value = value;
  d.where = where;
  return d;
}

InitialStressSpec geostatic(const std::string& region, double unit_weight, double k,
                            const std::string& where) {
  InitialStressSpec s;
  s.region = region;
  s.type = "geostatic";
  s.unit_weight = unit_weight;
  s.lateral_coefficient = k;
  s.surface = 0.0;
  s.where = where;
  return s;
}

} // namespace

ProblemSpec make_problem(const PileSpec& pile) {
  const auto& g = pile.geometry;
  const auto& m = pile.mesh;
  const double a = 0.5 * g.pile_diameter, L = g.pile_length;
  const double R = g.soil_radius, H = g.soil_depth;

  ProblemSpec p;
  p.file = pile.file;
  p.kinematics = "axisymmetric";
  p.mesh.has_blocks = true;
  p.mesh.cell = m.cell;
  p.mesh.where = pile.file + ": mesh";
  // AxisSegments grade along increasing coordinates; the input's growth factors go away from
  // the shaft and down from the toe / the head.
  p.mesh.x = axis(0.0, a, R, m.pile_radial_cells, m.soil_radial_cells, 1.0, m.radial_growth);
  p.mesh.y = axis(-H, -L, 0.0, m.below_toe_cells, m.shaft_cells, 1.0 / m.below_toe_growth,
                  1.0 / m.shaft_growth);
  p.mesh.block_regions = {kSoilToe, kSoil, kPile, kSoil};
  BoxSetSpec head{kHead, {0.0, 0.0}, {a, 0.0}, kPile, pile.pullout_where};
  p.mesh.box_sets.push_back(head);
  if (pile.rigid_soil) {
    p.mesh.box_sets.push_back({"soil_nodes", {0.0, -H}, {R, 0.0}, kSoil, pile.file});
    p.mesh.box_sets.push_back({"soil_below_toe_nodes", {0.0, -H}, {a, -L}, kSoilToe, pile.file});
  }

  MaterialSpec soil_toe = pile.soil;
  soil_toe.region = kSoilToe;
  p.materials = {pile.pile, pile.soil, soil_toe};
  p.linear_solver = pile.linear_solver;
  p.contact_solver = pile.contact_solver;

  // Geostatic stress: the soil's from its unit weight and K0; the pile gets its own vertical
  // stress (its weight) and the soil's horizontal stress, so that the shaft starts in
  // equilibrium with the soil's K0 gamma z.
  const double k0 = pile.geostatic.K0;
  const double gamma_soil =
      pile.soil.parameters.has("unit_weight") ? pile.soil.parameters.real("unit_weight") : 0.0;
  const double gamma_pile =
      pile.pile.parameters.has("unit_weight") ? pile.pile.parameters.real("unit_weight") : 0.0;
  if (gamma_soil > 0) {
    p.initial_stress.push_back(geostatic(kSoil, gamma_soil, k0, pile.geostatic_where));
    p.initial_stress.push_back(geostatic(kSoilToe, gamma_soil, k0, pile.geostatic_where));
  }
  if (gamma_pile > 0)
    p.initial_stress.push_back(
        geostatic(kPile, gamma_pile, k0 * gamma_soil / gamma_pile, pile.geostatic_where));

  for (const char* name : {kShaft, kToe}) {
    InterfaceSpec i;
    i.name = name;
    i.between = {kPile, name == kShaft ? kSoil : kSoilToe};
    i.law = pile.law;
    i.parameters = pile.law_parameters;
    i.where = pile.interface_where;
    p.interfaces.push_back(i);
  }

  // Supports: axis (u_r = 0), far side (u_r = 0), fixed base; every stage keeps gravity so
  // that the geostatic equilibrium carries over.
  auto supports = [&](StageSpec& s) {
    s.boundary_conditions.push_back(bc("left", 0, 0.0, s.where));
    s.boundary_conditions.push_back(bc("right", 0, 0.0, s.where));
    s.boundary_conditions.push_back(bc("bottom", 0, 0.0, s.where));
    s.boundary_conditions.push_back(bc("bottom", 1, 0.0, s.where));
    if (pile.rigid_soil)
      for (const char* set : {"soil_nodes", "soil_below_toe_nodes"})
        for (int c = 0; c < 2; ++c)
          s.boundary_conditions.push_back(bc(set, c, 0.0, s.where));
    LoadSpec gravity;
    gravity.type = LoadSpec::Type::Gravity;
    gravity.where = s.where;
    s.loads.push_back(gravity);
  };
  StageSpec geo;
  geo.name = "geostatic";
  geo.where = pile.geostatic_where;
  geo.reset_displacements = true;
  supports(geo);
  StageSpec install;
  install.name = "installation";
  install.where = pile.installation_where;
  install.increments = pile.installation.increments;
  supports(install);
  install.interface_gaps.push_back(
      {kShaft, -pile.installation.radial_displacement, pile.installation_where});
  StageSpec pull;
  pull.name = "pullout";
  pull.where = pile.pullout_where;
  pull.increments = pile.pullout.increments;
  pull.duration = pile.pullout.duration;
  pull.control.type = pile.pullout.control;
  pull.control.where = pile.pullout_where;
  pull.control.dissipation_step = pile.pullout.dissipation_step;
  pull.control.max_increments = pile.pullout.max_increments;
  pull.energy_tolerance = pile.pullout.energy_tolerance;
  supports(pull);
  pull.boundary_conditions.push_back(
      bc(kHead, 1, pile.pullout.head_displacement, pile.pullout_where));
  p.stages = {geo, install, pull};
  p.output = pile.output;
  check_stage_controls(p);
  return p;
}

} // namespace bipot::pile
