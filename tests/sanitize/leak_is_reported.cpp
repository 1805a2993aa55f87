// Leaks on purpose, from bipot's code, with MPI running (sanitized builds only): the suite
// checks that LeakSanitizer reports it, i.e. that the suppressions written for OpenMPI's and
// Gmsh's own leaks (lsan.supp) do not hide a leak in bipot.
#include "fem/linalg/parallel_environment.hpp"
#include "fem/mesh/structured_mesh.hpp"

#include <iostream>

namespace {

/// Builds a mesh on the heap and forgets it. Not inlined, so that no live frame of main
/// still holds the pointer when LeakSanitizer scans the stack at exit.
[[gnu::noinline]] void leak_a_mesh() {
  auto* mesh = new bipot::Mesh(bipot::make_rectangle(0.0, 1.0, 2, 0.0, 1.0, 2, bipot::CellType::Quad4));
  std::cout << "leaked a mesh of " << mesh->num_cells() << " cells" << std::endl;
}

} // namespace

int main(int argc, char** argv) {
  bipot::ParallelEnvironment env(argc, argv);
  leak_a_mesh();
  return 0;
}
