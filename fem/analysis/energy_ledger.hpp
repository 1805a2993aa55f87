#pragma once
/// The energy balance of a run, step by step (`energy.csv`): the work of the external forces
/// and of prescribed interface interferences against the energy stored in the bodies and the
/// interfaces and what the interfaces dissipate. The bulk terms are the trapezoidal rule over
/// the increment, exact for a linear bulk; each interface keeps its own account
/// (InterfaceEnforcement::record_energy). Where β falls, the adhesive springs' share of the
/// external work is integrated by a three-point rule (ThreePointRule, parameter: the chord
/// length ‖Δu‖ of the steps) through the last three states of a smooth stretch of the path,
/// a correction the interfaces compute pair by pair (the trapezoid at kinks and after
/// break_path()). What is left (`balance_error`) is that quadrature's error: the
/// discretisation error of the energy's measurement, not a solver error
/// (docs/energy_quadrature.md).

#include "fem/assembly/interface_enforcement.hpp"
#include "fem/core/state_arrays.hpp"

#include <memory>
#include <vector>

namespace bipot {

/// Cumulative energies since the start of the run (kJ; axisymmetric: full revolution).
struct EnergyTotals {
  double external_work = 0; ///< loads and support reactions on the bodies
  /// Of prescribed interface motions: gaps (installation) and moving rigid obstacles; and the
  /// change of the springs' energy when a stage puts another law in force.
  double interference_work = 0;
  double bulk_energy = 0;          ///< work of the internal forces (elastic energy, linear bulk)
  double interface_energy = 0;     ///< ½ β² (C_n g_n² + C_t ‖g_t‖²) A, now
  double adhesion_dissipation = 0; ///< w (β0 − β) A: adhesion lost
  double viscous_dissipation = 0;  ///< mean (β Ẽ − w)⁺ of the step × (β_old − β) A
  double contact_work = 0;         ///< of the irreversible traction r: friction (and contact)
  /// external + interference − (bulk + interface + adhesion + viscous + contact).
  double balance_error() const;
  /// |external| + |interference|: the work put in, the scale of the balance.
  double work_put_in() const;
  /// balance_error() / work_put_in() (0 while no work has been put in): energy.csv's
  /// relative_error.
  double relative_error() const;
};

class EnergyLedger {
public:
  /// Starts the interfaces' accounts at their committed state.
  explicit EnergyLedger(const std::vector<std::unique_ptr<InterfaceEnforcement>>& ifaces);

  /// After a converged increment, before the interfaces commit: u (all DOFs), the external
  /// forces (loads + reactions) and the internal forces at u, all replicated. `jump`: the
  /// increment jumped (the staggered fallback), so no path joins its states and no rule,
  /// exact or not, does better than the trapezoid; the path starts again after it.
  void record(const std::vector<double>& u, const std::vector<double>& external,
              const std::vector<double>& internal, bool jump = false);
  /// The totals record() would make of the same arguments, with the ledger and the
  /// interfaces' accounts left as they were: an increment is judged on its energy before it
  /// is committed (EnergyStepControl) and recorded only if it is kept.
  EnergyTotals trial(const std::vector<double>& u, const std::vector<double>& external,
                     const std::vector<double>& internal, bool jump = false);
  /// The displacements were reset to zero with the stresses kept (geostatic stage); the path
  /// starts again (break_path()).
  void reset_displacements();
  /// The path is not known to be smooth from the last recorded state on (a stage starts, a
  /// jump): the next step is integrated by the trapezoidal rule.
  void break_path() { last_chord_ = 0; }
  const EnergyTotals& totals() const { return totals_; }
  /// Its whole state for a checkpoint (energy_ledger_state.cpp): the totals, the last step's
  /// u and forces, its chord length, and every interface's account.
  StateArrays save_state() const;
  /// Restores save_state()'s arrays; throws bipot::Error if they do not fit.
  void load_state(const StateArrays& state);

private:
  const std::vector<std::unique_ptr<InterfaceEnforcement>>& ifaces_;
  EnergyTotals totals_;
  std::vector<double> u_, external_, internal_;
  /// ‖Δu‖ of the last recorded step; 0: the path starts again.
  double last_chord_ = 0;
};

} // namespace bipot
