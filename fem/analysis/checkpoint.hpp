#pragma once
/// Checkpoint files: the complete state of an analysis (StaticAnalysis::save_state()) in one
/// portable binary file, written by one rank from arrays every rank holds (the mesh is
/// replicated and the arrays are keyed by global node, cell and pair numbers, so a checkpoint
/// restores at any rank count).
///
/// Layout (little-endian): "BIPOTCKP", u32 format version, u32 length + bipot version,
/// u64 input hash, u64 number of arrays, then per array u32 length + name, u64 count and
/// count doubles (IEEE 754 binary64, bit-exact).

#include "fem/core/state_arrays.hpp"
#include "fem/input/problem_spec.hpp"

#include <cstdint>
#include <string>

namespace bipot {

/// Version of the layout above and of the arrays a complete state needs; a file of another
/// version is refused. 2: the energy step control's state (analysis.energy_control) and the
/// energy's part of the cut-back level (analysis.in_stage[6]), without which a restart judged
/// its increments' energy otherwise than the uninterrupted run; and two more values at the
/// head of every interface's energy account (a law change's work still to book, and whether
/// a step was recorded).
constexpr std::uint32_t checkpoint_format_version = 2;

/// The bipot version that writes checkpoints (the project's version).
std::string bipot_version();

/// FNV-1a (64 bit) of `bytes`, continuing from `hash` (to hash several pieces in turn).
std::uint64_t content_hash(const std::string& bytes, std::uint64_t hash = 14695981039346656037ull);

/// Hash of what the state depends on: the input file's bytes and, for a Gmsh mesh, the mesh
/// file's. A spec read from text (no such file) hashes `text` instead of the input file.
/// Throws bipot::Error if a file cannot be read.
std::uint64_t input_hash(const ProblemSpec& spec, const std::string& text = "");

/// Writes `state` to `path` atomically (a temporary file renamed into place), so that an
/// interrupted write never leaves a truncated checkpoint. Throws bipot::Error naming the path.
void write_checkpoint(const std::string& path, std::uint64_t input_hash, const StateArrays& state);

/// Reads a checkpoint, refusing (InputError "path: ... ", with the reason) a file that is not
/// a bipot checkpoint or is truncated, one of another format version or bipot version, or one
/// written for another input (`input_hash` differs: the input or its mesh changed).
StateArrays read_checkpoint(const std::string& path, std::uint64_t input_hash);

} // namespace bipot
