#include "apps/common/checkpoints.hpp"

#include "fem/analysis/checkpoint.hpp"
#include "fem/core/error.hpp"
#include "fem/linalg/communicator.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

namespace bipot::app {

namespace {

// Collective: every rank takes part in gathering the state, rank 0 writes it.
void write(const std::string& path, std::uint64_t hash, StateArrays state, const AppState& app) {
  if (app)
    for (auto& [name, values] : app())
      state[name] = std::move(values);
  if (mpi_rank() == 0) write_checkpoint(path, hash, state);
  barrier();
}

// Copies `name` from the checkpoint's folder into the new results, if it is there.
void copy_checkpoint(const std::filesystem::path& from, const std::string& to,
                     const std::string& name) {
  const std::filesystem::path ckp = from / name;
  if (!std::filesystem::exists(ckp)) return;
  std::error_code ec;
  std::filesystem::copy_file(ckp, std::filesystem::path(to) / name,
                             std::filesystem::copy_options::overwrite_existing, ec);
  if (ec) throw Error(ckp.string() + ": cannot copy it into the results: " + ec.message());
}

} // namespace

std::string checkpoint_name(const std::string& stage) {
  return "checkpoint_" + stage + ".bin";
}

std::string step_checkpoint_name(const std::string& stage, int k) {
  return "checkpoint_" + stage + "_step" + std::to_string(k) + ".bin";
}

std::function<void(std::size_t, double)> checkpoint_writer(const Model& model,
                                                           const StaticAnalysis* const* analysis,
                                                           std::string folder, AppState app) {
  if (model.spec.output.checkpoint_after.empty()) return {};
  const std::uint64_t hash = input_hash(model.spec);
  return [&model, analysis, folder = std::move(folder), hash, app](std::size_t done, double time) {
    const auto& names = model.spec.output.checkpoint_after;
    const std::string& stage = model.spec.stages[done - 1].name;
    if (std::find(names.begin(), names.end(), stage) == names.end()) return;
    write(folder + "/" + checkpoint_name(stage), hash, (*analysis)->save_state(done, time), app);
  };
}

std::function<void(const StepReport&)> step_checkpoint_writer(const Model& model,
                                                              const StaticAnalysis* const* analysis,
                                                              std::string folder, AppState app) {
  const OutputSpec& out = model.spec.output;
  if (out.checkpoint_steps.empty() && out.checkpoint_every == 0) return {};
  const std::uint64_t hash = input_hash(model.spec);
  return [&model, analysis, folder = std::move(folder), hash, app](const StepReport& r) {
    const StageSpec& stage = model.spec.stages[static_cast<std::size_t>(r.stage_index)];
    if (r.traced || !model.spec.output.checkpoint_at(stage, r.planned_step)) return;
    write(folder + "/" + step_checkpoint_name(stage.name, r.planned_step), hash,
          (*analysis)->save_step_state(), app);
  };
}

StateArrays read_restart(const std::string& file, const Model& model) {
  return read_checkpoint(file, input_hash(model.spec));
}

RestartPoint restore(const std::string& file, const StateArrays& state, StaticAnalysis& analysis,
                     ResultWriter& writer, const Model& model) {
  analysis.load_state(state);
  const std::vector<double>& position = state.at("analysis.position");
  RestartPoint p;
  p.stages_done = static_cast<std::size_t>(position[0]);
  p.global_steps = static_cast<int>(position[2]);
  double time = position[1];
  int planned = 0; // the planned level of the next stage the checkpoint was written at
  const auto in_stage = state.find("analysis.in_stage");
  if (in_stage != state.end()) {
    p.stage_steps = static_cast<int>(in_stage->second[3]);
    planned = static_cast<int>(in_stage->second[4]);
    time = in_stage->second[5];
    const StageSpec& st = model.spec.stages[p.stages_done];
    p.text = "at step " + std::to_string(p.stage_steps) + " of stage '" + st.name +
             "' (load level " + std::to_string(planned) + "/" + std::to_string(st.increments) + ")";
  } else {
    p.text = "after stage '" + model.spec.stages[p.stages_done - 1].name + "'";
  }
  std::string& from = p.folder;
  from = std::filesystem::path(file).parent_path().string();
  if (from.empty()) from = ".";
  writer.resume(from, p.stages_done, time, p.stage_steps);
  // The checkpoints written up to there, so that the new folder offers the same restarts.
  if (mpi_rank() == 0)
    for (const auto& entry : std::filesystem::directory_iterator(from)) {
      const std::string name = entry.path().filename().string();
      for (std::size_t s = 0; s <= p.stages_done && s < model.spec.stages.size(); ++s) {
        const StageSpec& st = model.spec.stages[s];
        const std::string prefix = "checkpoint_" + st.name + "_step";
        const int k = name.compare(0, prefix.size(), prefix) == 0
                          ? std::atoi(name.c_str() + prefix.size())
                          : 0;
        if ((s < p.stages_done && name == checkpoint_name(st.name)) ||
            (k > 0 && name == step_checkpoint_name(st.name, k) &&
             (s < p.stages_done || k <= planned)))
          copy_checkpoint(from, writer.directory(), name);
      }
    }
  barrier();
  return p;
}

} // namespace bipot::app
