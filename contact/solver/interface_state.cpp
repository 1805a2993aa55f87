// InterfaceAssembler's committed state for checkpoints, as flat arrays over its pairs.
#include "contact/solver/interface_assembler.hpp"

#include "fem/core/error.hpp"

namespace bipot::contact {

namespace {

void put(std::vector<double>& out, const std::vector<LocalVector>& v) {
  for (const auto& x : v)
    out.insert(out.end(), x.data(), x.data() + x.size());
}

} // namespace

StateArrays InterfaceAssembler::save_state() const {
  StateArrays out;
  std::vector<LocalVector> jump, r;
  for (const auto& s : committed_) {
    out["beta"].push_back(s.beta);
    jump.push_back(s.jump);
    r.push_back(s.r);
  }
  put(out["jump"], jump);
  put(out["r"], r);
  put(out["previous_r"], previous_r_);
  put(out["multiplier"], multiplier_);
  put(out["offset"], offset_);
  out["rho"] = rho_;
  out["gap_shift"] = {gap_shift_};
  return out;
}

void InterfaceAssembler::load_state(const StateArrays& state) {
  const std::size_t n = committed_.size();
  const auto get = [&](const std::string& name, std::size_t size) -> const std::vector<double>& {
    const auto it = state.find(name);
    if (it == state.end() || it->second.size() != size)
      throw Error("interface '" + iface_.name + "': the state has no array '" + name + "' of " +
                  std::to_string(size) + " values");
    return it->second;
  };
  const auto take = [&](const std::string& name, std::vector<LocalVector>& to) {
    const std::vector<double>& v = get(name, n * dim_);
    to.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      to[i] = Eigen::Map<const LocalVector>(v.data() + i * dim_, dim_);
  };
  std::vector<LocalVector> jump, r;
  take("jump", jump);
  take("r", r);
  take("previous_r", previous_r_);
  take("multiplier", multiplier_);
  take("offset", offset_);
  const std::vector<double>& beta = get("beta", n);
  rho_ = get("rho", n);
  gap_shift_ = get("gap_shift", 1)[0];
  for (std::size_t i = 0; i < n; ++i) {
    committed_[i].beta = beta[i];
    committed_[i].jump = jump[i];
    committed_[i].r = r[i];
    results_[i].beta = beta[i];
    results_[i].jump = jump[i];
    results_[i].r = r[i];
  }
  tangent_changed_ = true;
}

} // namespace bipot::contact
