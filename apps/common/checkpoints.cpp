#include "apps/common/checkpoints.hpp"

#include "fem/analysis/checkpoint.hpp"
#include "fem/core/error.hpp"
#include "fem/linalg/communicator.hpp"

#include <algorithm>
#include <filesystem>

namespace bipot::app {

namespace {

std::string checkpoint_name(const std::string& stage) {
  return "checkpoint_" + stage + ".bin";
}

} // namespace

std::function<void(std::size_t, double)>
checkpoint_writer(const Model& model, const StaticAnalysis* const* analysis, std::string folder) {
  const auto& names = model.spec.output.checkpoint_after;
  if (names.empty()) return {};
  const std::uint64_t hash = input_hash(model.spec);
  return [&model, analysis, folder = std::move(folder), hash](std::size_t done, double time) {
    const auto& names = model.spec.output.checkpoint_after;
    const std::string& stage = model.spec.stages[done - 1].name;
    if (std::find(names.begin(), names.end(), stage) == names.end()) return;
    const StateArrays state = (*analysis)->save_state(done, time);
    if (mpi_rank() == 0) write_checkpoint(folder + "/" + checkpoint_name(stage), hash, state);
    barrier();
  };
}

StateArrays read_restart(const std::string& file, const Model& model) {
  return read_checkpoint(file, input_hash(model.spec));
}

std::size_t restore(const std::string& file, const StateArrays& state, StaticAnalysis& analysis,
                    ResultWriter& writer, const Model& model) {
  analysis.load_state(state);
  const std::vector<double>& position = state.at("analysis.position");
  const auto done = static_cast<std::size_t>(position[0]);
  std::string from = std::filesystem::path(file).parent_path().string();
  if (from.empty()) from = ".";
  writer.resume(from, done, position[1]);
  if (mpi_rank() == 0)
    for (std::size_t s = 0; s < done; ++s) {
      const std::filesystem::path ckp =
          std::filesystem::path(from) / checkpoint_name(model.spec.stages[s].name);
      std::error_code ec;
      if (std::filesystem::exists(ckp))
        std::filesystem::copy_file(ckp, std::filesystem::path(writer.directory()) / ckp.filename(),
                                   std::filesystem::copy_options::overwrite_existing, ec);
      if (ec) throw Error(ckp.string() + ": cannot copy it into the results: " + ec.message());
    }
  barrier();
  return done;
}

} // namespace bipot::app
