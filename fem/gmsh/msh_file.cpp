#include "fem/gmsh/msh_file.hpp"

#include "fem/core/error.hpp"
#include "fem/gmsh/msh_cursor.hpp"
#include "fem/gmsh/msh_element_types.hpp"

#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <set>
#include <unordered_set>

namespace bipot::msh {

static_assert(sizeof(std::size_t) == 8, "MSH 4.1 binary files hold 8-byte size_t fields");

namespace {

constexpr long long kMaxTag = INT_MAX;
constexpr std::uint64_t kMaxCount = UINT64_MAX;

std::string dim_tag(int dim, long long tag) {
  return "(dimension " + std::to_string(dim) + ", tag " + std::to_string(tag) + ")";
}

class Parser {
public:
  Parser(const std::string& path, std::string_view text) : c_(path, text) {}

  File run() {
    header();
    while (!c_.at_end()) {
      const std::size_t at = c_.mark();
      const std::string_view w = c_.word();
      if (w.size() < 2 || w[0] != '$')
        c_.fail_at(at, "expected a section marker ($Name), found '" + printable(w) + "'");
      section(std::string(w.substr(1)), at);
    }
    if (!seen_.count("Nodes")) c_.fail("the file has no $Nodes section");
    if (!seen_.count("Elements")) c_.fail("the file has no $Elements section");
    return std::move(file_);
  }

private:
  static std::string printable(std::string_view w) {
    std::string s;
    for (std::size_t i = 0; i < w.size() && i < 24; ++i)
      s += (w[i] >= 0x20 && w[i] < 0x7f) ? w[i] : '?';
    return w.size() > 24 ? s + "..." : s;
  }

  void header() {
    if (c_.word() != "$MeshFormat")
      throw InputError(c_.path() + ": not a Gmsh MSH file (it does not start with $MeshFormat)");
    const std::size_t at = c_.mark();
    const std::string_view version = c_.word();
    if (version != "4.1")
      c_.fail_at(at, "MSH format version " + printable(version) +
                         " is not supported; re-export it with 'gmsh -format msh4'");
    binary_ = c_.integer("$MeshFormat: file type (0 ASCII, 1 binary)", 0, 1) == 1;
    c_.integer("$MeshFormat: data size (sizeof(size_t))", 8, 8);
    if (binary_) {
      // The integer 1, written in binary after the line: tells the byte order.
      if (!c_.line().empty()) c_.fail("$MeshFormat: unexpected text after the data size");
      c_.set_binary(true);
      if (c_.integer("$MeshFormat: byte-order mark", INT_MIN, INT_MAX) != 1)
        c_.fail("$MeshFormat: the binary file was written with another byte order");
      c_.set_binary(false);
    }
    c_.expect("$EndMeshFormat", "$MeshFormat");
    seen_.insert("MeshFormat");
  }

  void section(const std::string& name, std::size_t at) {
    if (name.rfind("End", 0) == 0)
      c_.fail_at(at, "$" + printable(name) + " without its opening $" + printable(name.substr(3)));
    const bool main = name == "MeshFormat" || name == "PhysicalNames" || name == "Entities" ||
                      name == "Nodes" || name == "Elements";
    if (main && !seen_.insert(name).second) c_.fail_at(at, "a second $" + name + " section");
    if ((name == "PhysicalNames" || name == "Entities") && seen_.count("Nodes"))
      c_.fail_at(at, "$" + name + " must come before $Nodes");
    if (name == "Elements" && !seen_.count("Nodes"))
      c_.fail_at(at, "$Elements must come after $Nodes");
    if (name == "PhysicalNames")
      physical_names();
    else if (name == "Entities")
      in_binary([&] { entities(); });
    else if (name == "Nodes")
      in_binary([&] { nodes(); });
    else if (name == "Elements")
      in_binary([&] { elements(); });
    else if (name == "PartitionedEntities")
      c_.fail_at(at, "partitioned meshes are not supported; save the mesh unpartitioned");
    else if (!c_.skip_past_line("$End" + name)) // e.g. $Comments, $NodeData: not used
      c_.fail_at(at, "section $" + printable(name) + " is not closed by $End" + printable(name));
    if (main) c_.expect("$End" + name, "$" + name);
  }

  template <class F> void in_binary(F&& read) {
    c_.set_binary(binary_);
    if (binary_ && !c_.line().empty()) c_.fail("unexpected text after the section marker");
    read();
    c_.set_binary(false);
  }

  void physical_names() {
    const std::uint64_t n = c_.count("$PhysicalNames: number of names", 0, c_.capacity(3, 0));
    for (std::uint64_t i = 0; i < n; ++i) {
      const std::string what = "$PhysicalNames: name " + std::to_string(i + 1);
      const int dim = int(c_.integer(what + ": dimension", 0, 3));
      const int tag = int(c_.integer(what + ": tag", 1, kMaxTag));
      const std::size_t at = c_.pos();
      std::string_view rest = c_.line();
      while (!rest.empty() && (rest.front() == ' ' || rest.front() == '\t'))
        rest.remove_prefix(1);
      while (!rest.empty() && (rest.back() == ' ' || rest.back() == '\t'))
        rest.remove_suffix(1);
      if (rest.size() < 2 || rest.front() != '"' || rest.back() != '"' ||
          rest.substr(1, rest.size() - 2).find('"') != std::string_view::npos)
        c_.fail_at(at, what + ": the name must be one \"quoted\" string on the line");
      const std::string_view name = rest.substr(1, rest.size() - 2);
      if (name.size() > kMaxNameLength)
        c_.fail_at(at, what + ": longer than " + std::to_string(kMaxNameLength) + " characters");
      for (const char ch : name)
        if (static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f)
          c_.fail_at(at, what + ": contains a control character");
      if (!file_.physical_names.emplace(DimTag{dim, tag}, std::string(name)).second)
        c_.fail_at(at, what + ": physical group " + dim_tag(dim, tag) + " is named twice");
    }
  }

  void entities() {
    std::uint64_t n[4];
    // Smallest entity: a point, tag + 3 coordinates + a physical count (5 words, 36 bytes).
    for (int d = 0; d < 4; ++d)
      n[d] = c_.count("$Entities: number of entities of dimension " + std::to_string(d), 0,
                      c_.capacity(5, 36));
    for (int d = 0; d < 4; ++d)
      for (std::uint64_t i = 0; i < n[d]; ++i) {
        const std::size_t at = c_.mark();
        const std::string what = "$Entities: entity of dimension " + std::to_string(d);
        const int tag = int(c_.integer(what + ": tag", 1, kMaxTag));
        const std::string named = "$Entities: entity " + dim_tag(d, tag);
        // Position (point) or bounding box: not used by bipot, only read.
        for (int k = 0; k < (d == 0 ? 3 : 6); ++k)
          c_.real(named + ": coordinate", false);
        const std::uint64_t np =
            c_.count(named + ": number of physical tags", 0, c_.capacity(1, 4));
        std::vector<int> physicals;
        std::set<int> seen; // not a scan of `physicals`: np is bounded by the file size only
        for (std::uint64_t p = 0; p < np; ++p) {
          const int phys = int(c_.integer(named + ": physical tag", 1, kMaxTag));
          if (!seen.insert(phys).second)
            c_.fail(named + ": physical tag " + std::to_string(phys) + " twice");
          physicals.push_back(phys);
        }
        if (d > 0) { // bounding entities: not used by bipot, only read
          const std::uint64_t nb =
              c_.count(named + ": number of bounding entities", 0, c_.capacity(1, 4));
          for (std::uint64_t b = 0; b < nb; ++b)
            c_.integer(named + ": bounding entity tag", -kMaxTag, kMaxTag);
        }
        if (!file_.entity_physicals.emplace(DimTag{d, tag}, std::move(physicals)).second)
          c_.fail_at(at, named + " is declared twice");
      }
    has_entities_ = true;
  }

  void check_entity(int dim, int tag, std::size_t at, const std::string& what) {
    if (has_entities_ && !file_.entity_physicals.count({dim, tag}))
      c_.fail_at(at, what + ": entity " + dim_tag(dim, tag) + " is not declared in $Entities");
  }

  /// The four size_t fields that open $Nodes and $Elements; `min_words`/`min_bytes` bound one
  /// entry. Returns {blocks, entries, min tag, max tag}.
  std::array<std::uint64_t, 4> counts(const std::string& section, std::size_t min_words,
                                      std::size_t min_bytes) {
    std::array<std::uint64_t, 4> h{};
    h[0] = c_.count(section + ": number of entity blocks", 0, c_.capacity(4, 20));
    h[1] = c_.count(section + ": total number", 0, c_.capacity(min_words, min_bytes));
    h[2] = c_.count(section + ": smallest tag", h[1] > 0 ? 1 : 0, kMaxCount);
    h[3] = c_.count(section + ": largest tag", h[2], kMaxCount);
    return h;
  }

  void nodes() {
    const auto [blocks, total, min_tag, max_tag] = counts("$Nodes", 4, 32);
    file_.node_tags.reserve(total);
    file_.node_coords.reserve(total);
    for (std::uint64_t b = 0; b < blocks; ++b) {
      const std::size_t at = c_.mark();
      const std::string what = "$Nodes block " + std::to_string(b + 1);
      const int dim = int(c_.integer(what + ": entity dimension", 0, 3));
      const int tag = int(c_.integer(what + ": entity tag", 1, kMaxTag));
      check_entity(dim, tag, at, what);
      const int parametric = int(c_.integer(what + ": parametric flag", 0, 1));
      const int per = 3 + parametric * dim;
      const std::uint64_t left = total - file_.node_tags.size();
      const std::uint64_t n = c_.count(what + ": number of nodes (with the blocks before, at "
                                              "most the header's total)",
                                       0, std::min(left, c_.capacity(1 + per, 8 * (1 + per))));
      const std::size_t first = file_.node_tags.size();
      // Field names made once per block, messages naming a node only on failure: this loop
      // runs once per node of the mesh.
      const std::string tag_what = what + ": node tag";
      for (std::uint64_t i = 0; i < n; ++i) {
        const std::size_t tag_at = c_.mark();
        const std::uint64_t node = c_.count(tag_what, min_tag, max_tag);
        if (!file_.node_of.emplace(node, file_.node_tags.size()).second)
          c_.fail_at(tag_at, what + ": node " + std::to_string(node) + " is defined twice");
        file_.node_tags.push_back(node);
      }
      const std::string coordinate_what[3] = {what + ": coordinate x", what + ": coordinate y",
                                              what + ": coordinate z"};
      const std::string parametric_what = what + ": parametric coordinate";
      for (std::uint64_t i = 0; i < n; ++i) {
        std::array<double, 3> x{};
        for (int k = 0; k < 3; ++k) {
          const std::size_t at = c_.mark();
          x[k] = c_.real(coordinate_what[k], false);
          if (!std::isfinite(x[k]))
            c_.fail_at(at, "$Nodes: node " + std::to_string(file_.node_tags[first + i]) +
                               ": coordinate " + "xyz"[k] + " is not a finite number");
        }
        for (int k = 0; k < per - 3; ++k)
          c_.real(parametric_what, false);
        file_.node_coords.push_back(x);
      }
    }
    if (file_.node_tags.size() != total)
      c_.fail_at(c_.mark(), "$Nodes: the header announces " + std::to_string(total) +
                                " nodes, the blocks hold " +
                                std::to_string(file_.node_tags.size()));
  }

  void elements() {
    const auto [blocks, total, min_tag, max_tag] = counts("$Elements", 2, 16);
    std::uint64_t read = 0;
    std::unordered_set<std::uint64_t> tags;
    for (std::uint64_t b = 0; b < blocks; ++b) {
      ElementBlock block;
      block.pos = c_.mark();
      const std::string what = "$Elements block " + std::to_string(b + 1);
      block.dim = int(c_.integer(what + ": entity dimension", 0, 3));
      block.entity = int(c_.integer(what + ": entity tag", 1, kMaxTag));
      check_entity(block.dim, block.entity, block.pos, what);
      const std::size_t type_at = c_.mark();
      block.type = int(c_.integer(what + ": element type", 1, kMaxTag));
      const ElementType* type = element_type(block.type);
      if (!type)
        c_.fail_at(type_at, what + ": unknown element type " + std::to_string(block.type) +
                                " (known: Gmsh types 1-31, 92, 93)");
      if (type->dim != block.dim)
        c_.fail_at(type_at, what + ": elements of type '" + type->name + "' (dimension " +
                                std::to_string(type->dim) + ") in an entity of dimension " +
                                std::to_string(block.dim));
      block.nodes_per_element = type->num_nodes;
      const std::size_t words = 1 + std::size_t(type->num_nodes);
      const std::uint64_t n =
          c_.count(what + ": number of elements (with the blocks before, at most the header's "
                          "total)",
                   0, std::min(total - read, c_.capacity(words, 8 * words)));
      read += n;
      block.tags.reserve(n);
      block.nodes.reserve(n * type->num_nodes);
      const std::string tag_what = what + ": element tag", node_what = what + ": node tag";
      for (std::uint64_t e = 0; e < n; ++e) {
        const std::size_t tag_at = c_.mark();
        const std::uint64_t tag = c_.count(tag_what, min_tag, max_tag);
        if (!tags.insert(tag).second)
          c_.fail_at(tag_at, what + ": element " + std::to_string(tag) + " is defined twice");
        block.tags.push_back(tag);
        for (int a = 0; a < type->num_nodes; ++a) {
          const std::size_t node_at = c_.mark();
          const std::uint64_t node = c_.count(node_what, 1, kMaxCount);
          if (!file_.node_of.count(node))
            c_.fail_at(node_at, what + ": element " + std::to_string(tag) + ": node " +
                                    std::to_string(node) + " is not defined in $Nodes");
          block.nodes.push_back(node);
        }
      }
      file_.element_blocks.push_back(std::move(block));
    }
    if (read != total)
      c_.fail_at(c_.mark(), "$Elements: the header announces " + std::to_string(total) +
                                " elements, the blocks hold " + std::to_string(read));
  }

  Cursor c_;
  File file_;
  bool binary_ = false;
  bool has_entities_ = false;
  std::set<std::string> seen_;
};

} // namespace

File parse(const std::string& path, std::string_view text) {
  return Parser(path, text).run();
}

} // namespace bipot::msh
