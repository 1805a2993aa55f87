// The strict .msh parser (fem/gmsh/msh_file.hpp): each malformed variant of a small valid file
// is refused with path:line and what is wrong; no truncation of a file is accepted; ASCII and
// binary forms of one mesh read identically; the reader agrees with libgmsh on the shipped mesh.
#include "fem/gmsh/gmsh_reader.hpp"

#include "fem/core/error.hpp"
#include "tests/support/scratch_dir.hpp"

#include <gmsh.h>
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace bipot {
namespace {

namespace fs = std::filesystem;

const std::string kCorpus = std::string(BIPOT_SOURCE_DIR) + "/tests/fuzz/corpus_msh/";

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

/// The lines of tests/fuzz/corpus_msh/tri.msh: one triangle, a physical point, curve and
/// surface (42 lines; line n is lines[n - 1]).
std::vector<std::string> tri_lines() {
  std::istringstream in(slurp(kCorpus + "tri.msh"));
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);)
    lines.push_back(l);
  return lines;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines)
    s += l + "\n";
  return s;
}

class MshFile : public ::testing::Test {
protected:
  test::ScratchDir scratch{"msh"};
  fs::path file = scratch.path / "m.msh";

  /// The error read_gmsh gives for `text` ("accepted" if none).
  std::string error(const std::string& text) {
    std::ofstream(file, std::ios::binary) << text;
    try {
      read_gmsh(file.string());
    } catch (const InputError& e) {
      return e.what();
    }
    return "accepted";
  }
  /// tri.msh with line `n` replaced by `text` (several lines if it holds line breaks).
  std::string with_line(int n, const std::string& text) {
    auto lines = tri_lines();
    lines.at(std::size_t(n - 1)) = text;
    return error(joined(lines));
  }
  std::string at(int line) { return file.string() + ":" + std::to_string(line) + ": "; }
};

/// `msg` names the file and `line` (0: any place) and holds `text`.
#define EXPECT_MSG(msg, line, text)                                                                \
  do {                                                                                             \
    const std::string m = (msg);                                                                   \
    if (line > 0) {                                                                                \
      EXPECT_EQ(m.rfind(at(line), 0), 0u) << m;                                                    \
    }                                                                                              \
    EXPECT_NE(m.find(text), std::string::npos) << m;                                               \
  } while (0)

TEST_F(MshFile, ValidBaseIsAccepted) {
  ASSERT_EQ(tri_lines().size(), 42u);
  EXPECT_EQ(error(joined(tri_lines())), "accepted");
}

TEST_F(MshFile, MarkersPairedAndInOrder) {
  EXPECT_MSG(with_line(33, "$EndNode"), 33, "$Nodes: expected $EndNodes, found '$EndNode'");
  EXPECT_MSG(with_line(9, "$EndEntities"), 9,
             "$PhysicalNames: expected $EndPhysicalNames, found '$EndEntities'");
  auto lines = tri_lines(); // $Elements (lines 34-42) moved before $Nodes (20-33)
  std::vector<std::string> swapped(lines.begin(), lines.begin() + 19);
  swapped.insert(swapped.end(), lines.begin() + 33, lines.end());
  swapped.insert(swapped.end(), lines.begin() + 19, lines.begin() + 33);
  EXPECT_MSG(error(joined(swapped)), 20, "$Elements must come after $Nodes");
  EXPECT_MSG(with_line(42, "$EndElements\n$EndFoo"), 43, "$EndFoo without its opening $Foo");
  EXPECT_MSG(with_line(42, "$EndElements\n$Comments\nnever closed"), 43,
             "section $Comments is not closed by $EndComments");
  EXPECT_MSG(with_line(42, "$EndElements\n$Nodes\n0 0 0 0\n$EndNodes"), 43,
             "a second $Nodes section");
  EXPECT_MSG(with_line(42, "$EndElements\n$PartitionedEntities"), 43,
             "partitioned meshes are not supported");
  EXPECT_MSG(error(joined(std::vector<std::string>(lines.begin(), lines.begin() + 33))), 0,
             "the file has no $Elements section");
}

TEST_F(MshFile, UnusedSectionsAreSkipped) {
  EXPECT_EQ(with_line(42, "$EndElements\n$Comments\n$Nodes is not a marker here\n$EndComments\n"
                          "$NodeData\n1\n\"u\"\n$EndNodeData"),
            "accepted");
}

TEST_F(MshFile, CountsMatchEntriesAndFitTheFile) {
  EXPECT_MSG(with_line(21, "5 4 1 3"), 33,
             "$Nodes: the header announces 4 nodes, the blocks hold 3");
  EXPECT_MSG(with_line(21, "5 2 1 3"), 28, "$Nodes block 3: number of nodes");
  EXPECT_MSG(with_line(35, "3 2 1 3"), 40, "$Elements block 3: number of elements");
  // 10^12 nodes cannot be in a file of 450 bytes: refused before anything is allocated.
  EXPECT_MSG(with_line(21, "5 1000000000000 1 3"), 21, "$Nodes: total number is 1000000000000");
  EXPECT_MSG(with_line(5, "99999999999999999999"), 5,
             "$PhysicalNames: number of names: expected a non-negative integer");
  EXPECT_MSG(with_line(11, "3 3 1 -1"), 11, "$Entities: number of entities of dimension 3");
}

TEST_F(MshFile, TagsInRangeAndUnique) {
  EXPECT_MSG(with_line(29, "4"), 29, "$Nodes block 3: node tag is 4, outside [1, 3]");
  EXPECT_MSG(with_line(29, "2"), 29, "$Nodes block 3: node 2 is defined twice");
  EXPECT_MSG(with_line(41, "1 1 2 3"), 41, "$Elements block 3: element 1 is defined twice");
  EXPECT_MSG(with_line(22, "0 9 0 1"), 22,
             "$Nodes block 1: entity (dimension 0, tag 9) is not declared in $Entities");
  EXPECT_MSG(with_line(40, "2 1 2 1\n3 1 2 7"), 41,
             "$Elements block 3: element 3: node 7 is not defined in $Nodes");
  EXPECT_MSG(with_line(12, "1 0 0 0 1 0"), 12, "physical tag is 0, outside [1, 2147483647]");
}

TEST_F(MshFile, ElementTypesKnownWithTheirDimension) {
  EXPECT_MSG(with_line(40, "2 1 99 1"), 40,
             "$Elements block 3: unknown element type 99 (known: Gmsh types 1-31, 92, 93)");
  EXPECT_MSG(with_line(40, "2 1 1 1"), 40,
             "elements of type 'Line 2' (dimension 1) in an entity of dimension 2");
  // A quad block needs four nodes per element: the fourth word is the $EndElements marker.
  EXPECT_MSG(with_line(40, "2 1 3 1"), 42, "node tag: expected a non-negative integer");
}

TEST_F(MshFile, PhysicalNamesWellFormed) {
  EXPECT_MSG(with_line(8, "2 1 body"), 8, "name 3: the name must be one \"quoted\" string");
  EXPECT_MSG(with_line(8, "2 1 \"bo\"dy\""), 8, "must be one \"quoted\" string");
  EXPECT_MSG(with_line(8, "4 1 \"body\""), 8, "name 3: dimension is 4, outside [0, 3]");
  EXPECT_MSG(with_line(8, "2 1 \"" + std::string(128, 'a') + "\""), 8,
             "name 3: longer than 127 characters");
  EXPECT_EQ(with_line(8, "2 1 \"" + std::string(127, 'a') + "\""), "accepted");
  EXPECT_MSG(with_line(8, "1 2 \"again\""), 8,
             "physical group (dimension 1, tag 2) is named twice");
}

TEST_F(MshFile, CoordinatesFinite) {
  EXPECT_MSG(with_line(27, "1 nan 0"), 27, "$Nodes: node 2: coordinate y is not a finite");
  EXPECT_MSG(with_line(27, "1 0 inf"), 27, "$Nodes: node 2: coordinate z is not a finite");
  EXPECT_MSG(with_line(27, "1 0 1e999"), 27, "coordinate z is not a finite number");
  EXPECT_MSG(with_line(27, "1 0 0x"), 27, "coordinate z: expected a number, found '0x'");
}

TEST_F(MshFile, FormatAndStart) {
  EXPECT_MSG(with_line(2, "4.0 0 8"), 2, "MSH format version 4.0 is not supported");
  EXPECT_MSG(with_line(2, "4.1 2 8"), 2, "file type (0 ASCII, 1 binary) is 2");
  EXPECT_MSG(with_line(2, "4.1 0 4"), 2, "data size (sizeof(size_t)) is 4");
  EXPECT_MSG(with_line(1, "$MeshFormats"), 0, "not a Gmsh MSH file");
  // A device that never ends is refused from its first bytes, not read into memory.
  try {
    read_gmsh("/dev/zero");
    ADD_FAILURE() << "accepted /dev/zero";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find("/dev/zero: not a Gmsh MSH file"), 0u);
  }
}

/// Cuts at every length: none is a valid file (the $EndElements marker is incomplete), so each
/// must be refused with an InputError; ASCII and binary.
TEST_F(MshFile, EveryTruncationIsRefused) {
  for (const char* name : {"tri.msh", "tri_binary.msh"}) {
    const std::string text = slurp(kCorpus + name);
    ASSERT_GT(text.size(), 400u);
    int refused = 0;
    for (std::size_t n = 0; n + 1 < text.size(); ++n) // the last byte is the final line break
      refused += error(text.substr(0, n)) != "accepted";
    EXPECT_EQ(refused, int(text.size()) - 1) << name;
  }
  // Counts are bounded by what the rest of the file can hold: 27 bytes, one 20-byte block.
  const std::string binary = slurp(kCorpus + "tri_binary.msh");
  EXPECT_MSG(error(binary.substr(0, binary.find("$Nodes\n") + 27)), 0,
             "$Nodes: number of entity blocks is 5, outside [0, 1]");
}

TEST_F(MshFile, Gmsh48CrashInputsAreRefused) {
  // Inputs on which libgmsh 4.8's reader crashed (minimised fuzzer finds, docs/testing.md):
  // each is malformed, so each must be refused, with the file named at a line.
  int seen = 0;
  for (const auto& entry : fs::directory_iterator(kCorpus)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("gmsh48_", 0) != 0) continue;
    ++seen;
    try {
      read_gmsh(entry.path().string());
      ADD_FAILURE() << name << " accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).find(entry.path().string() + ":"), 0u) << e.what();
    }
  }
  EXPECT_EQ(seen, 17);
}

bool same(const Mesh& a, const Mesh& b) {
  return a.dim == b.dim && a.nodes == b.nodes && a.cell_types == b.cell_types &&
         a.cell_nodes == b.cell_nodes && a.cell_regions == b.cell_regions &&
         a.regions == b.regions && a.node_sets == b.node_sets &&
         a.facet_sets.size() == b.facet_sets.size();
}

TEST_F(MshFile, AsciiAndBinaryFormsReadIdentically) {
  // The two corpus files hold the same mesh, written by Gmsh in each form.
  const Mesh ascii = read_gmsh(kCorpus + "tri.msh");
  const Mesh binary = read_gmsh(kCorpus + "tri_binary.msh");
  EXPECT_TRUE(same(ascii, binary));
  EXPECT_EQ(ascii.num_cells(), 1);
  EXPECT_EQ(ascii.node_sets.at("corner").size(), 1u);
  EXPECT_EQ(ascii.facet_sets.at("bottom").size(), 1u);
}

TEST_F(MshFile, AgreesWithLibgmshOnTheShippedMesh) {
  // Independent reading: libgmsh's own, element counts and node coordinate sums per group.
  const std::string path = std::string(BIPOT_SOURCE_DIR) + "/inputs/meshes/square_with_regions.msh";
  const Mesh m = read_gmsh(path);
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::open(path);
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, 2);
  ASSERT_EQ(groups.size(), m.regions.size());
  for (const auto& [dim, tag] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(dim, tag, name);
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
    std::size_t count = 0;
    double sum[2] = {0, 0};
    for (int entity : entities) {
      std::vector<int> types;
      std::vector<std::vector<std::size_t>> tags, nodes;
      gmsh::model::mesh::getElements(types, tags, nodes, dim, entity);
      for (std::size_t t = 0; t < types.size(); ++t) {
        count += tags[t].size();
        for (std::size_t node : nodes[t]) {
          std::vector<double> x, u;
          gmsh::model::mesh::getNode(node, x, u);
          sum[0] += x[0];
          sum[1] += x[1];
        }
      }
    }
    std::size_t ours = 0;
    double our_sum[2] = {0, 0};
    for (Index c = 0; c < m.num_cells(); ++c) {
      if (m.cell_regions[c] != m.regions.at(name)) continue;
      ++ours;
      for (int a = 0; a < m.cell_num_nodes(c); ++a)
        for (int k = 0; k < 2; ++k)
          our_sum[k] += m.nodes[m.cell(c)[a]][k];
    }
    EXPECT_EQ(ours, count) << name;
    for (int k = 0; k < 2; ++k) // same doubles, summed in another order: round-off only
      EXPECT_NEAR(our_sum[k], sum[k], 1e-12 * count) << name;
  }
  gmsh::finalize();
}

} // namespace
} // namespace bipot
