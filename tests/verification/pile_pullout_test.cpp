// The pile pull-out app (apps/pile_pullout) against closed forms (issue 4):
//   1. shear-lag head stiffness of a pile on linear interface springs in rigid soil,
//   2. the adhesion peak of a long pile in rigid soil (energy balance of a debonding bar),
//   3. Randolph & Wroth's (1978) head stiffness of a bonded pile in elastic soil,
//   4. the geostatic stage: shaft contact pressure K0 γ |z|, stresses kept by the reset.
// Each problem goes through the app's own input reader and problem layout
// (read_pile_text → make_problem → build_model), so the test checks what the app runs.
#include "apps/catalogue/builtin_catalogue.hpp"
#include "apps/pile_pullout/pile_input.hpp"
#include "apps/pile_pullout/pile_problem.hpp"
#include "apps/pile_pullout/pile_results.hpp"

#include "fem/analysis/model.hpp"
#include "fem/analysis/static_analysis.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace bipot {
namespace {

constexpr double pi = 3.14159265358979323846;
// Pile of the seed paper (also the shipped inputs): D = 0.27 m, E = 3e6 kPa.
constexpr double D = 0.27, a = 0.5 * D, E_pile = 3.0e6;
const double area = pi * a * a, EA = E_pile * area;

using StepFn = std::function<void(const StepReport&, const Model&, const StaticAnalysis&)>;

void run(const ProblemSpec& problem, const StepFn& on_step) {
  const Model model = build_model(problem, bipot::builtin_catalogue());
  StaticAnalysis analysis(model);
  analysis.run([&](const StepReport& r) { on_step(r, model, analysis); });
}

std::size_t interface_index(const Model& model, const std::string& name) {
  for (std::size_t k = 0; k < model.interfaces.size(); ++k)
    if (model.interfaces[k].name == name) return k;
  ADD_FAILURE() << "no interface " << name;
  return 0;
}

std::string text(double v) {
  std::ostringstream os;
  os.precision(17);
  os << v;
  return os.str();
}

// A pile in rigid soil (every soil node fixed): only the pile and the interface springs
// deform, so one soil cell across and below is enough. Pile ν = 0 (no radial contraction,
// so the shaft's normal jump stays 0) and no weight (the geostatic stage is then empty).
std::string rigid_soil_input(double length, int shaft_cells, int pile_radial_cells,
                             const std::string& rccm, double head_displacement, int increments) {
  return "geometry: {pile_diameter: 0.27, pile_length: " + text(length) +
         ", soil_radius: 0.5, soil_depth: " + text(length + 0.5) +
         "}\n"
         "mesh: {cell: tri3, pile_radial_cells: " +
         std::to_string(pile_radial_cells) + ", shaft_cells: " + std::to_string(shaft_cells) +
         ", soil_radial_cells: 1, below_toe_cells: 1}\n"
         "materials:\n"
         "  pile: {type: linear_elastic, youngs_modulus: 3.0e6, poissons_ratio: 0.0}\n"
         "  soil: {type: linear_elastic, youngs_modulus: 3.0e4, poissons_ratio: 0.33}\n"
         "rigid_soil: true\n"
         "interface: {law: rccm, parameters: {" +
         rccm +
         "}}\n"
         "linear_solver: {method: direct}\n"
         "contact_solver: {type: semismooth_newton}\n"
         "stages:\n"
         "  geostatic: {K0: 0.43}\n"
         "  installation: {radial_displacement: 0.0, increments: 1}\n"
         "  pullout: {head_displacement: " +
         text(head_displacement) + ", increments: " + std::to_string(increments) + "}\n";
}

// 1. Shear lag. With the soil rigid, the pile is a bar (EA) on shaft springs C_t per unit
// area (per unit length k_s = 2π a C_t) with a toe spring: the toe is an RCCM interface of
// area π a², which the pull opens by g_n = u_toe, so it pulls back with C_n π a² u_toe
// (r = 0 in opening; nothing tangential with ν = 0): k_b = C_n π a². EA u'' = k_s u with
// EA u'(toe) = k_b u(toe) gives, with x the height above the toe,
//   u(x) = u_toe (cosh λx + (k_b / EAλ) sinh λx),   λ² = k_s / EA,
//   K = P / u_head = EAλ (k_b + EAλ tanh λL) / (EAλ + k_b tanh λL),
//   toe force k_b u_toe = k_b u_head / (cosh λL + (k_b / EAλ) sinh λL).
// C_t = 2700 kN/m³ gives λL = 1.50 and C_n = 2e5 kN/m³ gives k_b = 0.58 EAλ, so the head
// stiffness lies between the free-toe (EAλ tanh λL) and fixed-toe (EAλ / tanh λL) values,
// 7 % from each: both ends matter. w = 1e6 kJ/m² keeps β = 1 (E = C g² ~ 1e-5 ≪ w).
void check_shear_lag(double Ct, double Cn) {
  const double L = 13.0, u_head = 1.0e-4;
  const std::string rccm = "normal_stiffness: " + text(Cn) + ", tangential_stiffness: " + text(Ct) +
                           ", decohesion_energy: 1.0e6, friction_coefficient: 0.0";
  // 52 cells of 0.25 m along the shaft (λh = 0.029) and 3 across the pile: the lumped
  // springs and linear elements err by O((λh)²/12) ≈ 1e-4 and the shear deformation of the
  // pile section by O((λa)²/2) ≈ 1e-4; refining to 104 × 6 changes K by < 1e-4 (measured).
  const auto spec = pile::read_pile_text(rigid_soil_input(L, 52, 3, rccm, u_head, 1), "lag.yaml",
                                         bipot::builtin_catalogue());
  pile::HeadState head;
  double toe_force = 0;
  run(pile::make_problem(spec), [&](const StepReport& r, const Model& m, const StaticAnalysis& s) {
    if (r.stage != "pullout") return;
    head = pile::head_state(m, s);
    toe_force = s.interfaces()[interface_index(m, pile::kToe)]->resultant()[1];
  });
  const double lambda = std::sqrt(Ct * 2 * pi * a / EA), kb = Cn * area;
  const double t = std::tanh(lambda * L), eal = EA * lambda;
  const double K = eal * (kb + eal * t) / (eal + kb * t);
  const double toe = kb * u_head / (std::cosh(lambda * L) + kb / eal * std::sinh(lambda * L));
  std::printf("shear lag: lambda L = %.4f, K = %.2f kN/m (closed form %.2f), toe force %.4f kN "
              "(closed form %.4f)\n",
              lambda * L, head.force / head.displacement, K, toe_force, toe);
  ASSERT_NEAR(head.displacement, u_head, 1e-12); // the head moved as prescribed
  // 1 %: the bound; the discretisation errors above are 100 times smaller.
  EXPECT_NEAR(head.force / head.displacement, K, 0.01 * K);
  // The toe spring carries 17 % of the pull; the same 1 % bound on it.
  EXPECT_NEAR(toe_force, toe, 0.01 * toe);
}

TEST(PilePullout, ShearLagHeadStiffness) {
  check_shear_lag(2700.0, 2.0e5);
}

// A softer interface (λL = 0.5, the toe then carries most of the pull). It also guards a
// fixed solver bug: a multiplier update right after the matrix was rebuilt left the old
// factorisation in use, and this case failed with a linear-solver residual of 2e-3.
TEST(PilePullout, ShearLagSoftInterface) {
  check_shear_lag(300.0, 2.0e4);
}

// 2. Adhesion peak of a long pile. Rigid soil, RCCM shaft with μ = 0 and α = 0: per unit
// area the shear traction is τ(s) = C_t s up to s* = √(w/C_t), then w²/(C_t s³), and
// Φ(s) = ∫₀ˢ τ = w − w²/(2 C_t s²) beyond s* (→ w). Multiplying EA u'' = πD τ(u) by u' and
// integrating over the pile (u = slip, rigid soil) gives the energy balance
//   P² = 2 EA πD [Φ(δ) − Φ(u_toe)] + N_toe²,
// δ the head displacement, u_toe and N_toe the toe's displacement and force. While the toe
// barely moves, P → P∞ = √(2 w EA πD): the steady-state debonding force. C_t = 2e4 kN/m³,
// w = 0.08 kJ/m² (s* = 2 mm) and L = 20 m (λL = 6.3): the pull reaches δ ≈ 6 s* with the
// toe still bonded; from 1D runs, the front reaches the toe at δ ≈ 14.5 mm, where the rest
// of the bond snaps at once (a snap-back: the force drops to the debonded tail's ~1 kN).
TEST(PilePullout, LongPileAdhesionPeak) {
  const double L = 20.0, Ct = 2.0e4, w = 0.08, delta_end = 0.016;
  const int increments = 32;
  const std::string rccm = "normal_stiffness: 2.0e4, tangential_stiffness: 2.0e4, "
                           "decohesion_energy: 0.08, friction_coefficient: 0.0, "
                           "adhesion_viscosity: 0.0";
  // 0.25 m cells along the shaft and 0.5 mm steps: the softening zone (slip s* → 3 s*) is
  // ~3 m long, 12 cells. A 1D bar model of the same problem (same cells and steps) gives the
  // peak 0.05 % below this one, and halving its cells moves the peak by 2e-5.
  const auto spec = pile::read_pile_text(rigid_soil_input(L, 80, 2, rccm, delta_end, increments),
                                         "adhesion.yaml", bipot::builtin_catalogue());
  struct Step {
    double delta, force, u_toe, toe_force;
    bool unstable;
  };
  std::vector<Step> steps;
  run(pile::make_problem(spec), [&](const StepReport& r, const Model& m, const StaticAnalysis& s) {
    if (r.stage != "pullout") return;
    const auto head = pile::head_state(m, s);
    const std::size_t toe = interface_index(m, pile::kToe);
    double u_toe = 0; // mean upward displacement of the pile's toe nodes
    for (const auto& p : m.interfaces[toe].pairs)
      u_toe += s.displacement()[s.dofs().dof(p.node_a, 1)];
    u_toe /= static_cast<double>(m.interfaces[toe].pairs.size());
    steps.push_back(
        {head.displacement, head.force, u_toe, s.interfaces()[toe]->resultant()[1], r.unstable});
  });
  ASSERT_FALSE(steps.empty());
  EXPECT_NEAR(steps.back().delta, delta_end, 1e-12); // the run did not stop early

  const double P_inf = std::sqrt(2 * w * EA * pi * D), s_star = std::sqrt(w / Ct);
  auto phi = [&](double s) {
    return s <= s_star ? 0.5 * Ct * s * s : w - w * w / (2 * Ct * s * s);
  };
  const auto peak = std::max_element(
      steps.begin(), steps.end(), [](const Step& x, const Step& y) { return x.force < y.force; });
  std::printf("adhesion peak: %.2f kN at %.2f mm (sqrt(2 w EA pi D) = %.2f kN, %+.2f %%)\n",
              peak->force, 1e3 * peak->delta, P_inf, 100 * (peak->force / P_inf - 1));
  // 3 %: the bound. The peak lies below P∞ by the tail of the law not yet used up,
  // P/P∞ = √(Φ(δ)/w) = 0.99 at δ = 10 mm, and by the toe's share, both checked below.
  EXPECT_NEAR(peak->force, P_inf, 0.03 * P_inf);

  // The energy balance at every step up to the peak, with the model's own u_toe and N_toe:
  // a sharper check than the peak alone. Measured within 0.18 %: 0.06 % on the elastic
  // branch (the pile section's shear deformation, which the bar model leaves out), ±0.1–0.2 %
  // once debonding runs (the lumped node pairs soften one 0.25 m cell at a time, so the
  // discrete Φ is a staircase of the continuous one). 0.5 % leaves room for both.
  for (auto it = steps.begin(); it <= peak; ++it) {
    const double P2 =
        2 * EA * pi * D * (phi(it->delta) - phi(it->u_toe)) + it->toe_force * it->toe_force;
    EXPECT_NEAR(it->force, std::sqrt(P2), 0.005 * std::sqrt(P2))
        << "at head displacement " << 1e3 * it->delta << " mm";
  }

  // After the peak the front reaches the toe and the remaining bond breaks within one step:
  // the force falls below 5 % of P∞ (the debonded tail) and the analysis flags the step.
  const auto drop =
      std::find_if(peak, steps.end(), [&](const Step& x) { return x.force < 0.05 * P_inf; });
  ASSERT_NE(drop, steps.end()) << "the bond did not break by " << 1e3 * delta_end << " mm";
  std::printf("adhesion: snap-back at %.2f mm, %.2f -> %.2f kN, flagged unstable: %d\n",
              1e3 * drop->delta, (drop - 1)->force, drop->force, drop->unstable ? 1 : 0);
  EXPECT_GT((drop - 1)->force, 0.9 * P_inf); // one step, from near the plateau
  EXPECT_TRUE(drop->unstable);
}

// 3. Randolph & Wroth (1978): head stiffness of a compressible pile bonded to homogeneous
// elastic soil (ρ = 1, η = ξ = 1):
//   P/(w G r0) = [4/(1−ν) + (2π/ζ)(tanh μL/μL)(L/r0)] / [1 + (4/(πλ(1−ν)))(tanh μL/μL)(L/r0)],
//   λ = E_p/G, ζ = ln(r_m/r0), r_m = 2.5 L ρ (1 − ν), μL = √(2/(ζλ)) L/r0.
// (Transcription checked against an independent implementation of the same paper's
// formula found with the search tools; the paper itself was not available.) Pull-out and
// push-in stiffnesses are equal for linear elasticity with a bonded toe.
double randolph_wroth_stiffness(double Ep, double Es, double nu, double r0, double L) {
  const double G = Es / (2 * (1 + nu)), lambda = Ep / G;
  const double zeta = std::log(2.5 * L * (1 - nu) / r0);
  const double muL = std::sqrt(2 / (zeta * lambda)) * L / r0, t = std::tanh(muL) / muL;
  return G * r0 * (4 / (1 - nu) + 2 * pi / zeta * t * L / r0) /
         (1 + 4 / (pi * lambda * (1 - nu)) * t * L / r0);
}

// The shipped pile and soil, bonded, weightless; `cell` and the soil's extent vary.
std::string bonded_input(const std::string& cell, double radius, double depth, int radial_cells,
                         int below_toe_cells) {
  return "geometry: {pile_diameter: 0.27, pile_length: 13.0, soil_radius: " + text(radius) +
         ", soil_depth: " + text(depth) + "}\nmesh: {cell: " + cell +
         ", pile_radial_cells: 3, shaft_cells: 52, soil_radial_cells: " +
         std::to_string(radial_cells) +
         ", radial_growth: 1.15, below_toe_cells: " + std::to_string(below_toe_cells) +
         ", below_toe_growth: 1.15}\n"
         "materials:\n"
         "  pile: {type: linear_elastic, youngs_modulus: 3.0e6, poissons_ratio: 0.3}\n"
         "  soil: {type: linear_elastic, youngs_modulus: 3.0e4, poissons_ratio: 0.33}\n"
         "interface: {law: perfect_bonding}\n"
         "linear_solver: {method: direct}\n"
         "stages:\n"
         "  geostatic: {K0: 0.43}\n"
         "  installation: {radial_displacement: 0.0, increments: 1}\n"
         "  pullout: {head_displacement: 1.0e-3, increments: 1}\n";
}

double bonded_head_stiffness(const std::string& input) {
  double K = 0;
  run(pile::make_problem(pile::read_pile_text(input, "bonded.yaml", bipot::builtin_catalogue())),
      [&](const StepReport& r, const Model& m, const StaticAnalysis& s) {
        if (r.stage != "pullout") return;
        const auto head = pile::head_state(m, s);
        K = head.force / head.displacement;
      });
  return K;
}

// Measured head stiffnesses (MN/m; closed form 48.89):
//   tri3, the shipped cell layout:       20/26 m 55.58, 40/52 m 54.64 (−1.7 %), 80/104 m 54.19
//   quad8, same cell layout:             40/52 m 53.97, 80/104 m 53.53 (−0.8 %), 160/208 m 53.32
//   quad8 80/104 m with every cell halved: 53.47 (−0.1 %: the quad8 mesh is converged)
// tri3 is 1.2 % stiff on this mesh, and the domain still takes ~1 % from 40/52 to the
// extrapolated infinite one (≈ 53.1). The converged continuum is 8.6 % stiffer than the
// closed form: that is Randolph & Wroth's approximation, not the mesh or the domain (the
// model's stiffness corresponds to r_m ≈ 10 m in their formula instead of 2.5 L(1 − ν) =
// 21.8 m; a plausible reason: r_m was calibrated with the full length, while this
// compressible pile, μL = 3.7, sheds 85 % of the load in its upper half). So the test uses
// quad8 on the two larger domains: with tri3 at 40/52 the 10 % bound fails (+11.8 %), by
// discretisation and domain errors that the quad8 runs remove.
TEST(PilePullout, BondedHeadStiffnessRandolphWroth) {
  const double K40 = bonded_head_stiffness(bonded_input("quad8", 40, 52, 35, 25));
  const double K80 = bonded_head_stiffness(bonded_input("quad8", 80, 104, 40, 30));
  const double K_rw = randolph_wroth_stiffness(E_pile, 3.0e4, 0.33, a, 13.0);
  std::printf("Randolph-Wroth: K = %.1f kN/m (40 m x 52 m), %.1f kN/m (80 m x 104 m); closed "
              "form %.1f kN/m (%+.2f %%)\n",
              K40, K80, K_rw, 100 * (K80 / K_rw - 1));
  // Domain convergence: doubling the soil's radius and depth changes K by < 2 % (issue).
  EXPECT_NEAR(K40, K80, 0.02 * K80);
  // 10 %: the bound, about the accuracy Randolph & Wroth claim for their closed form.
  EXPECT_NEAR(K80, K_rw, 0.10 * K_rw);
}

// 4. The geostatic stage. Initial stress σ_v = −γ|z|, σ_h = K0 σ_v in the soil; the pile gets
// its own weight vertically and the soil's K0 γ|z| horizontally, so the shaft's contact
// pressure should be p = K0 γ|z|. Equilibrium is solved, then displacements are reset
// keeping stresses and interface forces.
std::string shipped_rccm_text() {
  std::ifstream in(std::string(BIPOT_SOURCE_DIR) + "/inputs/pile_pullout/rccm.yaml");
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

// A node pair: position along its interface (z on the shaft, r on the toe), contact
// pressure (kPa), weight (m²).
struct PairState {
  double x, p, weight;
};
struct GeostaticState {
  std::vector<PairState> shaft, toe;
  double max_u = 0;                              ///< largest displacement component (m)
  std::vector<std::array<double, 6>> soil_cells; ///< r, z of the centroid, σ_rr, σ_zz, σ_θθ, σ_rz
};

GeostaticState snapshot(const Model& m, const StaticAnalysis& s) {
  GeostaticState g;
  for (double v : s.displacement())
    g.max_u = std::max(g.max_u, std::abs(v));
  for (const char* name : {pile::kShaft, pile::kToe}) {
    const std::size_t k = interface_index(m, name);
    const auto& pairs = m.interfaces[k].pairs;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      const auto& x = m.mesh.nodes[pairs[i].node_a];
      const double p = s.interfaces()[k]->results()[i].r(0);
      (name == pile::kShaft ? g.shaft : g.toe)
          .push_back({name == pile::kShaft ? x[1] : x[0], p, pairs[i].weight});
    }
  }
  std::vector<Index> cells;
  std::vector<double> strain, stress;
  s.cell_results(cells, strain, stress);
  const int soil = m.mesh.regions.at("soil");
  for (std::size_t c = 0; c < cells.size(); ++c) {
    if (m.mesh.cell_regions[cells[c]] != soil) continue;
    const Index* nodes = m.mesh.cell(cells[c]);
    const int n = m.mesh.cell_num_nodes(cells[c]);
    double r = 0, z = 0;
    for (int j = 0; j < n; ++j)
      r += m.mesh.nodes[nodes[j]][0] / n, z += m.mesh.nodes[nodes[j]][1] / n;
    g.soil_cells.push_back(
        {r, z, stress[4 * c], stress[4 * c + 1], stress[4 * c + 2], stress[4 * c + 3]});
  }
  return g;
}

// Runs the geostatic stage and then an installation stage that changes nothing (no
// interference): returns the states at the end of each (the last step of a stage wins).
std::pair<GeostaticState, GeostaticState> geostatic_and_rest(pile::PileSpec spec) {
  spec.installation.radial_displacement = 0.0;
  spec.installation.increments = 1;
  ProblemSpec problem = pile::make_problem(spec);
  problem.stages.resize(2); // no pull-out
  std::pair<GeostaticState, GeostaticState> out;
  run(problem, [&](const StepReport& r, const Model& m, const StaticAnalysis& s) {
    (r.stage == "geostatic" ? out.first : out.second) = snapshot(m, s);
  });
  return out;
}

// Largest |p − K0 γ|z|| (kPa) and largest |p − K0 γ|z|| / (K0 γ|z|) over the shaft pairs
// with depth in [from, to].
struct PressureError {
  double absolute = 0, relative = 0;
};
PressureError pressure_error(const std::vector<PairState>& shaft, double K0, double gamma,
                             double from, double to) {
  PressureError e;
  for (const auto& p : shaft) {
    const double depth = -p.x, expected = K0 * gamma * depth;
    if (depth < from - 1e-9 || depth > to + 1e-9) continue;
    e.absolute = std::max(e.absolute, std::abs(p.p - expected));
    if (expected > 0) e.relative = std::max(e.relative, std::abs(p.p - expected) / expected);
  }
  return e;
}

// The shipped RCCM input: its K0, unit weights and mesh (tri3). Measured along the shaft:
// p − K0 γ|z| ≈ +0.05…+0.09 kPa at every pair between the ends (0.2 % at 6 m, 2.8 % at
// 0.25 m where K0 γ|z| is 1.9 kPa). Two causes, both found by changing one thing:
//   - the tri3 cells integrate the initial stress at one point: the offset is O(h²) (0.09 →
//     0.025 kPa with the cells halved) and drops to ≤ 0.006 kPa at mid-depth with quad4/quad8;
//   - the pile (24 kN/m³) is heavier than the soil (18): its initial σ_zz = −γ_p L at the toe
//     meets the soil's −γ_s L below, so 4.5 kN of pile weight are out of balance. The pile
//     settles (5.6e-5 m before the reset), drags the shaft and perturbs p, most near the toe
//     (+0.38 kPa at 0.25 m above it, −1.7 kPa at the toe corner).
// With equal unit weights and quad8 cells both go and p = K0 γ|z| to 2e-7 of K0 γL at every pair
// (next test). The end pairs (z = 0 and the toe corner) have half weights: with linear
// cells their traction is the average of p over their half cell (K0 γ h/3 = 0.65 kPa at the
// head), so they are left to the next test; so are the pairs shallower than 1 m for the 2 %
// check (the offset is over 2 % of K0 γ|z| there), which the absolute check still covers.
TEST(PilePullout, GeostaticStageShippedInput) {
  const pile::PileSpec spec =
      pile::read_pile_text(shipped_rccm_text(), "rccm.yaml", bipot::builtin_catalogue());
  const double K0 = spec.geostatic.K0, gamma = spec.soil.parameters.real("unit_weight");
  const double L = spec.geometry.pile_length;
  const auto [geo, rest] = geostatic_and_rest(spec);
  ASSERT_FALSE(geo.shaft.empty());
  ASSERT_EQ(geo.shaft.size(), rest.shaft.size());
  ASSERT_EQ(geo.soil_cells.size(), rest.soil_cells.size());
  const double h = L / static_cast<double>(spec.mesh.shaft_cells);
  const PressureError deep = pressure_error(geo.shaft, K0, gamma, 1.0, L - 0.5 * h);
  const PressureError shallow = pressure_error(geo.shaft, K0, gamma, 0.5 * h, 1.0);
  std::printf("geostatic (shipped input): p vs K0 gamma |z|: %.2f %% (%.3f kPa) from 1 m to the "
              "toe, %.3f kPa above 1 m; max |u| %.2e m before the reset, %.2e m after\n",
              100 * deep.relative, deep.absolute, shallow.absolute, geo.max_u, rest.max_u);
  EXPECT_LT(deep.relative, 0.02); // the 2 %
  // Above 1 m: 0.2 % of the largest pressure, twice the 0.09 kPa measured.
  EXPECT_LT(shallow.absolute, 0.002 * K0 * gamma * L);

  // The soil keeps σ_v = γ z and σ_h = K0 γ z. Cells within 1 m of the toe corner carry the
  // pile's excess weight (up to 2.7 % off) and are left out; elsewhere below 1 m the
  // largest difference is 0.55 % (tri3 one-point stresses), hence 1 %.
  int checked = 0;
  for (const auto* state : {&geo, &rest})
    for (const auto& c : state->soil_cells) {
      if (c[1] > -1.0 || std::hypot(c[0] - a, c[1] + L) < 1.0) continue;
      const double sv = gamma * c[1], sh = K0 * sv;
      EXPECT_NEAR(c[2], sh, 0.01 * std::abs(sh)) << "σ_rr at r " << c[0] << ", z " << c[1];
      EXPECT_NEAR(c[3], sv, 0.01 * std::abs(sv)) << "σ_zz at r " << c[0] << ", z " << c[1];
      EXPECT_NEAR(c[4], sh, 0.01 * std::abs(sh)) << "σ_θθ at r " << c[0] << ", z " << c[1];
      EXPECT_NEAR(c[5], 0.0, 0.01 * std::abs(sv)) << "σ_rz at r " << c[0] << ", z " << c[1];
      ++checked;
    }
  EXPECT_GT(checked, 1000);

  // After the reset the state is an equilibrium: a stage that changes nothing leaves u at 0
  // (up to the Newton tolerance, 1e-8 of the forces) and the pressures and stresses as they
  // were. Measured: 3.7e-11 m against 5.6e-5 m before the reset, changes ≤ 1e-5 kPa.
  EXPECT_LT(rest.max_u, 1e-5 * geo.max_u);
  for (std::size_t i = 0; i < geo.shaft.size(); ++i)
    EXPECT_NEAR(rest.shaft[i].p, geo.shaft[i].p, 1e-5 * K0 * gamma * L)
        << "pair at z " << geo.shaft[i].x;
  double change = 0;
  for (std::size_t i = 0; i < geo.soil_cells.size(); ++i)
    for (int j = 2; j < 6; ++j)
      change = std::max(change, std::abs(geo.soil_cells[i][j] - rest.soil_cells[i][j]));
  EXPECT_LT(change, 1e-5 * gamma * spec.geometry.soil_depth);
}

// The same with the pile as heavy as the soil and quadratic cells: the geostatic stress is
// then an exact equilibrium of the discrete model (linear stress, integrated exactly by
// quad8; the end pairs' half-cell average of a linear p is their nodal value for quadratic
// shape functions), so nothing moves and every pair, ends included, has p = K0 γ|z|, every
// toe pair γL. 1e-4 of the largest value: what is left is the Newton tolerance's (1e-8 of
// the nodal forces, whose scale is the soil's weight) — measured 2e-7 K0 γL on the shaft and
// 3e-6 γL on the toe, whose pairs are small — and still 200 times below the 2 % above.
TEST(PilePullout, GeostaticStageIsExactForEqualUnitWeights) {
  pile::PileSpec spec =
      pile::read_pile_text(shipped_rccm_text(), "rccm.yaml", bipot::builtin_catalogue());
  const double K0 = spec.geostatic.K0, gamma = spec.soil.parameters.real("unit_weight");
  const double L = spec.geometry.pile_length;
  spec.pile.parameters.set("unit_weight", gamma);
  spec.mesh.cell = "quad8";
  const GeostaticState geo = geostatic_and_rest(spec).first;
  const PressureError e = pressure_error(geo.shaft, K0, gamma, 0.0, L);
  double toe_error = 0;
  int toe_pairs = 0;
  for (const auto& p : geo.toe)
    if (p.weight > 0) { // the pair on the axis has no area (r = 0) and no meaningful traction
      toe_error = std::max(toe_error, std::abs(p.p - gamma * L));
      ++toe_pairs;
    }
  std::printf("geostatic (equal unit weights, quad8): shaft p - K0 gamma |z| up to %.2e kPa, "
              "toe p - gamma L up to %.2e kPa, max |u| %.2e m\n",
              e.absolute, toe_error, geo.max_u);
  EXPECT_LT(e.absolute, 1e-4 * K0 * gamma * L);
  EXPECT_LT(toe_error, 1e-4 * gamma * L);
  EXPECT_GT(toe_pairs, 3);
  EXPECT_LT(geo.max_u, 1e-9); // against 5.6e-5 m of pile settlement with the shipped weights
}

} // namespace
} // namespace bipot
