#pragma once
/// Time series output for ParaView: one XML .vtu piece per MPI rank and step, a .pvtu per step
/// when running on several ranks, and a .pvd collection listing every completed step.

#include "fem/core/types.hpp"
#include "fem/mesh/mesh.hpp"

#include <string>
#include <vector>

namespace bipot {

/// A named field of `components` values per entity, components interleaved
/// ([e0c0, e0c1, ..., e1c0, ...]).
struct Field {
  std::string name;
  int components = 1;
  std::vector<double> values;
  /// If set, the values are read from there instead of `values`, which stays empty: a field
  /// the caller keeps anyway (the displacement) is written without a copy.
  const std::vector<double>* view = nullptr;
  const std::vector<double>& data() const { return view ? *view : values; }
};

/// Writes a series of unstructured-grid steps.
///
/// Files, in `directory`: `<basename>_<step:04d>_<rank>.vtu` (every rank: its cells and the
/// nodes they use; raw binary appended data), `<basename>_<step:04d>.pvtu` (rank 0, only when
/// size > 1) and `<basename>.pvd` (rank 0, rewritten after each step through a temporary file
/// and std::rename, so an interrupted run always leaves a valid collection). The .pvd
/// references the .pvtu (size > 1) or the .vtu (size == 1) of each step.
///
/// 2D meshes are written with z = 0 and 2-component fields padded to 3 components with 0
/// (ParaView's "Warp By Vector" needs 3). Every piece also gets an Int32 cell field "region"
/// with the mesh region id of each cell.
///
/// The writer does no MPI: the caller calls write_step on every rank, and must barrier after
/// it before anything reads the .pvtu/.pvd (rank 0 writes them without waiting for the other
/// ranks' pieces).
class VtkSeriesWriter {
public:
  /// Creates `directory` (and parents) if needed; rank in [0, size). Throws bipot::Error if the
  /// directory cannot be created or rank/size are invalid.
  VtkSeriesWriter(std::string directory, std::string basename, int rank, int size);

  /// Writes one step at pseudo-time `time`. `cells`: the cells of this rank (mesh cell ids).
  /// `point_fields`: values for ALL mesh nodes in global numbering (this rank's nodes are
  /// picked out). `cell_fields`: values for the listed cells, in the order of `cells`.
  /// Throws bipot::Error on a size mismatch, a duplicate or reserved ("region") field name, an
  /// invalid cell id or a failed write (message names the file).
  void write_step(double time, const Mesh& mesh, const std::vector<Index>& cells,
                  const std::vector<Field>& point_fields, const std::vector<Field>& cell_fields);

  /// Continues the series of an earlier run in `directory` (a restart): its steps up to
  /// pseudo-time `time` (relative tolerance 1e-12) are listed first in the .pvd, and rank 0
  /// copies their files (a .pvtu with its pieces) into this writer's directory. Call before
  /// the first write_step(), on every rank. Throws bipot::Error if the earlier .pvd or a file
  /// it names cannot be read or copied.
  void resume(const std::string& directory, double time);

  /// Number of steps written so far (= index of the next step).
  int num_steps() const { return static_cast<int>(times_.size()); }
  /// File name (without directory) of a step's piece of a rank.
  std::string piece_name(int step, int rank) const;
  /// File name (without directory) of a step's .pvtu.
  std::string pvtu_name(int step) const;
  /// Full path of the .pvd collection.
  std::string pvd_path() const;

private:
  void write_pvtu(int step, int dim, const std::vector<Field>& point_fields,
                  const std::vector<Field>& cell_fields) const;
  void write_pvd() const;
  std::string path(const std::string& name) const;

  std::string directory_;
  std::string basename_;
  int rank_;
  int size_;
  std::vector<double> times_;      ///< time of every completed step
  std::vector<std::string> files_; ///< the file the .pvd lists for each step
};

} // namespace bipot
