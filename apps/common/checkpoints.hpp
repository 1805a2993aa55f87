#pragma once
/// What the apps do for `output.checkpoint` and `run --restart FILE` (docs/input_reference.md,
/// "Checkpoints and restart"): checkpoints are written at stage ends into the results folder;
/// a restart continues after the stage its checkpoint closed, and its results folder starts
/// with the earlier run's results up to there, copied from the checkpoint's folder.

#include "fem/analysis/model.hpp"
#include "fem/analysis/result_writer.hpp"
#include "fem/analysis/static_analysis.hpp"
#include "fem/core/state_arrays.hpp"

#include <functional>
#include <string>

namespace bipot::app {

/// AnalysisOptions::on_stage_end writing `<folder>/checkpoint_<stage>.bin` at the end of the
/// stages output.checkpoint names (collective: every rank gathers, rank 0 writes).
/// `*analysis` must point to the running analysis when a stage ends.
std::function<void(std::size_t, double)>
checkpoint_writer(const Model& model, const StaticAnalysis* const* analysis, std::string folder);

/// Reads a checkpoint to restart `model` from (every rank), refusing one of another input or
/// version (InputError naming the file and the reason).
StateArrays read_restart(const std::string& file, const Model& model);

/// Restores `state` (read from `file`) into `analysis` and copies the earlier results from the
/// folder of `file` into `writer`'s: CSV rows and VTK steps up to the checkpoint, and the
/// checkpoints of the stages done. Every rank, before run(). Returns the stages done.
std::size_t restore(const std::string& file, const StateArrays& state, StaticAnalysis& analysis,
                    ResultWriter& writer, const Model& model);

} // namespace bipot::app
