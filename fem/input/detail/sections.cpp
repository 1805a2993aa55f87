#include "fem/input/detail/sections.hpp"

#include "fem/core/nearest_name.hpp"
#include "fem/input/problem_reader.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace bipot::input {

namespace {

AxisSegments read_axis(const YamlMap& parent, const std::string& key) {
  AxisSegments axis;
  YamlMap m(parent.node(key), parent.path(key), parent.diag(), {"breaks", "cells", "grading"});
  if (!m.valid()) return axis;
  m.reals("breaks", axis.breaks, true);
  m.integers("cells", axis.cells, true);
  m.reals("grading", axis.grading);
  const std::size_t segments = axis.breaks.empty() ? 0 : axis.breaks.size() - 1;
  if (axis.breaks.size() == 1) m.error("breaks", "need at least two break points");
  for (std::size_t i = 1; i < axis.breaks.size(); ++i)
    if (!(axis.breaks[i] > axis.breaks[i - 1]))
      m.error("breaks", "break points must increase strictly");
  if (!axis.cells.empty() && axis.cells.size() != segments)
    m.error("cells", "expected " + std::to_string(segments) +
                         " cell counts (one per segment), got " +
                         std::to_string(axis.cells.size()));
  for (int c : axis.cells)
    if (c < 1) m.error("cells", "cell counts must be at least 1");
  if (axis.grading.empty())
    axis.grading.assign(segments, 1.0);
  else if (axis.grading.size() != segments)
    m.error("grading", "expected " + std::to_string(segments) + " grading ratios, got " +
                           std::to_string(axis.grading.size()));
  for (double g : axis.grading)
    if (!(g > 0)) m.error("grading", "grading ratios must be > 0");
  return axis;
}

// The cells a blocks mesh would have (0 while its description is inconsistent), in floating
// point: three int counts multiply beyond any integer type.
double block_mesh_cells(const MeshSpec& mesh, int dim) {
  std::vector<const AxisSegments*> axes = {&mesh.x, &mesh.y};
  if (dim == 3) axes.push_back(&mesh.z);
  std::vector<std::size_t> segments;
  std::size_t blocks = 1;
  for (const AxisSegments* a : axes) {
    if (a->breaks.size() < 2 || a->cells.size() != a->breaks.size() - 1) return 0;
    segments.push_back(a->cells.size());
    blocks *= a->cells.size();
  }
  if (mesh.block_regions.size() != blocks) return 0;
  double cells = 0;
  for (std::size_t b = 0; b < blocks; ++b) {
    if (mesh.block_regions[b].empty()) continue; // a hole
    double in_block = 1;
    for (std::size_t i = 0, rest = b; i < axes.size(); rest /= segments[i], ++i)
      in_block *= axes[i]->cells[rest % segments[i]];
    cells += in_block;
  }
  const bool simplices = mesh.cell == "tri3" || mesh.cell == "tri6" || mesh.cell == "tet4";
  if (mesh.diagonals == "crossed" && mesh.cell == "tri3") return cells * 4;
  return cells * (simplices ? (dim == 3 ? 6 : 2) : 1);
}

} // namespace

MeshSpec read_mesh(const YamlMap& top, int dim, const std::string& base_dir) {
  MeshSpec mesh;
  YamlMap m(top.node("mesh"), "mesh", top.diag(), {"file", "blocks", "sets"});
  mesh.where = top.where("mesh");
  if (!m.valid()) return mesh;
  if (m.has("file") == m.has("blocks")) {
    top.error("mesh", "give exactly one of 'file' (a Gmsh .msh) or 'blocks' (structured)");
    return mesh;
  }
  if (m.has("sets")) {
    const YAML::Node sets = m.node("sets");
    if (!sets.IsMap()) m.error("sets", "expected a map: name -> {min: [...], max: [...]}");
    report_duplicate_keys(sets, "mesh.sets", top.diag());
    for (const auto& kv : sets.IsMap() ? sets : YAML::Node()) {
      BoxSetSpec box;
      box.name = kv.first.Scalar();
      const std::string path = "mesh.sets." + box.name;
      YamlMap b(kv.second, path, top.diag(), {"min", "max", "region"});
      if (!b.valid()) continue;
      box.where = top.diag().where(kv.first, path);
      b.reals("min", box.min, true);
      b.reals("max", box.max, true);
      b.string("region", box.region);
      for (const char* key : {"min", "max"}) {
        const auto& v = std::string(key) == "min" ? box.min : box.max;
        if (b.has(key) && static_cast<int>(v.size()) != dim)
          b.error(key, "expected " + std::to_string(dim) + " coordinates");
      }
      bool ordered = true;
      for (std::size_t i = 0; i < box.min.size() && i < box.max.size(); ++i)
        ordered = ordered && box.min[i] <= box.max[i];
      if (!ordered) b.error("max", "each max must be >= its min");
      mesh.box_sets.push_back(box);
    }
  }
  if (m.string("file", mesh.file) && m.has("file")) {
    mesh.where = m.where("file");
    std::filesystem::path p(mesh.file);
    if (p.is_relative() && !base_dir.empty()) p = std::filesystem::path(base_dir) / p;
    mesh.file = p.string();
    if (!std::filesystem::exists(p)) m.error("file", "mesh file not found: " + mesh.file);
  }
  if (m.has("blocks")) {
    mesh.has_blocks = true;
    std::vector<std::string> keys = {"cell", "x", "y", "regions", "diagonals"};
    if (dim == 3) keys.insert(keys.begin() + 3, "z");
    YamlMap b(m.node("blocks"), "mesh.blocks", top.diag(), keys);
    if (!b.valid()) return mesh;
    mesh.where = m.where("blocks");
    b.string("cell", mesh.cell);
    const std::vector<std::string> cells2 = {"tri3", "tri6", "quad4", "quad8"};
    const std::vector<std::string> cells3 = {"tet4", "hex8"};
    const auto& allowed = dim == 3 ? cells3 : cells2;
    if (std::find(allowed.begin(), allowed.end(), mesh.cell) == allowed.end())
      b.error("cell", "cell type '" + mesh.cell + "' is not available in " + std::to_string(dim) +
                          "D; allowed: " + join_names(allowed));
    if (b.has("diagonals")) {
      b.string("diagonals", mesh.diagonals);
      const std::vector<std::string> patterns = {"right", "left", "alternating", "crossed"};
      const bool triangles = mesh.cell == "tri3" || mesh.cell == "tri6";
      if (std::find(patterns.begin(), patterns.end(), mesh.diagonals) == patterns.end())
        b.error("diagonals", "unknown diagonal pattern '" + mesh.diagonals +
                                 "'; allowed: " + join_names(patterns));
      else if (!triangles && std::find(allowed.begin(), allowed.end(), mesh.cell) != allowed.end())
        b.error("diagonals",
                "diagonals applies to triangle cells (tri3, tri6), not to " + mesh.cell);
      else if (mesh.diagonals == "crossed" && mesh.cell != "tri3")
        b.error("diagonals", "diagonals 'crossed' (4 triangles around a centre node) is "
                             "available for tri3 cells only");
    }
    for (const char* axis : {"x", "y", "z"}) {
      if (std::string(axis) == "z" && dim == 2) continue;
      AxisSegments& a = axis[0] == 'x' ? mesh.x : (axis[0] == 'y' ? mesh.y : mesh.z);
      if (b.has(axis))
        a = read_axis(b, axis);
      else
        b.missing(axis, "breaks, cells and optional grading along this axis");
    }
    b.strings("regions", mesh.block_regions, true);
    std::size_t blocks = std::max<std::size_t>(mesh.x.breaks.size(), 1) - 1;
    blocks *= std::max<std::size_t>(mesh.y.breaks.size(), 1) - 1;
    if (dim == 3) blocks *= std::max<std::size_t>(mesh.z.breaks.size(), 1) - 1;
    if (b.has("regions") && blocks > 0 && mesh.block_regions.size() != blocks)
      b.error("regions", "expected " + std::to_string(blocks) +
                             " region names (one per block, x fastest), got " +
                             std::to_string(mesh.block_regions.size()));
    const double cells = block_mesh_cells(mesh, dim);
    if (cells > max_block_mesh_cells) {
      char count[32];
      std::snprintf(count, sizeof count, cells < 1e18 ? "%.0f" : "%.3g", cells);
      m.error("blocks", "the mesh would have " + std::string(count) + " cells, more than the " +
                            std::to_string(max_block_mesh_cells) + " accepted");
    }
  }
  return mesh;
}

namespace {

// A list of reals: "" and the entries, or what is wrong with the node itself. An entry that is
// not a number is reported here, at its own line as path[i]; then `bad` is set.
std::string decode_real_list(const YAML::Node& v, const std::string& path, Diagnostics& diag,
                             std::vector<double>& out, bool& bad) {
  if (!v.IsSequence()) return "expected a list of real numbers, got " + describe_node(v);
  for (std::size_t i = 0; i < v.size(); ++i) {
    double d = 0;
    if (!decode_real(v[i], d)) {
      diag.error(v[i], index_path(path, i), "expected a real number, got " + describe_node(v[i]));
      bad = true;
    }
    out.push_back(d);
  }
  return "";
}

} // namespace

ParameterSet read_parameters_node(const YAML::Node& node, const std::string& path,
                                  Diagnostics& diag, const ParamSchema& schema,
                                  const std::vector<std::string>& skip, const ParameterSet* base) {
  ParameterSet params = base ? *base : ParameterSet{};
  if (!node.IsMap()) {
    diag.error(node, path, "expected a map of parameters, got " + describe_node(node));
    return params;
  }
  report_duplicate_keys(node, path, diag);
  std::map<std::string, YAML::Node> key_nodes, value_nodes;
  for (const auto& kv : node) {
    const std::string key = kv.first.Scalar();
    if (std::find(skip.begin(), skip.end(), key) != skip.end()) continue;
    key_nodes[key] = kv.first;
    value_nodes[key] = kv.second;
    const ParamSpec* spec = schema.find(key);
    const YAML::Node& v = kv.second;
    ParamValue value = v.IsScalar() ? ParamValue(v.Scalar()) : ParamValue(describe_node(v));
    if (spec) {
      double d = 0;
      int i = 0;
      bool b = false, bad_entry = false;
      std::vector<double> list;
      std::string problem;
      const auto expect = [&](bool ok, const char* what) {
        if (!ok) problem = std::string("expected ") + what + ", got " + describe_node(v);
      };
      switch (spec->type) {
      case ParamType::Real:
        expect(decode_real(v, d), "a real number");
        value = d;
        break;
      case ParamType::Integer: // consumers take an int: a larger value must not wrap
        problem = decode_int(v, i);
        value = static_cast<long>(i);
        break;
      case ParamType::Boolean:
        expect(decode_boolean(v, b), "true or false");
        value = b;
        break;
      case ParamType::String:
        expect(v.IsScalar(), "a string");
        break;
      case ParamType::RealList:
        problem = decode_real_list(v, join_path(path, key), diag, list, bad_entry);
        value = list;
        break;
      }
      if (!problem.empty()) diag.error(kv.first, join_path(path, key), problem);
      if (!problem.empty() || bad_entry) continue;
    }
    params.set(key, value);
  }
  const auto problems = validate(schema, params);
  for (const auto& p : problems) {
    const std::string at_path =
        p.entry ? index_path(join_path(path, p.key), *p.entry) : join_path(path, p.key);
    const auto list = value_nodes.find(p.key);
    if (p.entry && list != value_nodes.end()) { // a list's entry, at its own line
      const YAML::Node& entries = list->second;
      diag.error(entries[*p.entry], at_path, p.message);
      continue;
    }
    auto it = key_nodes.find(p.key);
    const YAML::Node& at = it != key_nodes.end() ? it->second : node;
    diag.error(at, at_path, p.message);
  }
  return params;
}

ParameterSet read_parameters(const YamlMap& parent, const std::string& key,
                             const ParamSchema& schema, const std::vector<std::string>& skip) {
  return read_parameters_node(parent.node(key), parent.path(key), parent.diag(), schema, skip);
}

ParameterSet read_schema_keys(const YamlMap& m, const ParamSchema& schema) {
  std::vector<std::string> others;
  for (const auto& kv : m.self())
    if (!schema.find(kv.first.Scalar())) others.push_back(kv.first.Scalar());
  return read_parameters_node(m.self(), m.path(), m.diag(), schema, others);
}

std::vector<MaterialSpec> read_materials(const YamlMap& top, const SchemaIndex& registry) {
  std::vector<MaterialSpec> out;
  const YAML::Node node = top.node("materials");
  if (!node.IsMap() || node.size() == 0) {
    top.error("materials", "expected a map: region name -> {type: <material>, parameters...}");
    return out;
  }
  report_duplicate_keys(node, "materials", top.diag());
  for (const auto& kv : node) {
    MaterialSpec mat;
    mat.region = kv.first.Scalar();
    const std::string path = "materials." + mat.region;
    mat.where = top.diag().where(kv.first, path);
    const YAML::Node& body = kv.second;
    if (!body.IsMap() || !body["type"]) {
      top.diag().error(body, path,
                       "expected {type: <material>, ...}; registered materials: " +
                           join_names(registry.names()));
      continue;
    }
    const YAML::Node type = body["type"];
    mat.type = type.Scalar();
    if (!registry.contains(mat.type)) {
      top.diag().error(type, path + ".type", registry.unknown_message(mat.type));
      continue;
    }
    mat.parameters =
        read_parameters_node(body, path, top.diag(), registry.schema(mat.type), {"type"});
    out.push_back(std::move(mat));
  }
  return out;
}

std::vector<InitialStressSpec> read_initial_stress(const YamlMap& top, int dim) {
  std::vector<InitialStressSpec> out;
  const YAML::Node list = top.node("initial_stress");
  if (!list.IsSequence()) {
    top.error("initial_stress", "expected a list of {region, type, ...}");
    return out;
  }
  for (std::size_t i = 0; i < list.size(); ++i) {
    InitialStressSpec s;
    const std::string path = index_path("initial_stress", i);
    YamlMap m(list[i], path, top.diag(),
              {"region", "type", "unit_weight", "lateral_coefficient", "surface", "stress"});
    if (!m.valid()) continue;
    s.where = m.where("region");
    m.string("region", s.region, true);
    m.string("type", s.type, true);
    if (s.type == "geostatic") {
      if (m.real("unit_weight", s.unit_weight, true) && !(s.unit_weight >= 0))
        m.error("unit_weight", "value must be >= 0 kN/m^3");
      if (m.real("lateral_coefficient", s.lateral_coefficient, true) &&
          !(s.lateral_coefficient >= 0))
        m.error("lateral_coefficient", "value must be >= 0");
      m.real("surface", s.surface, true);
    } else if (s.type == "constant") {
      if (m.reals("stress", s.stress, true) && m.has("stress") &&
          static_cast<int>(s.stress.size()) != (dim == 2 ? 4 : 6))
        m.error("stress", std::string("expected ") + (dim == 2 ? "4" : "6") +
                              " Voigt components (tension positive)");
    } else if (!s.type.empty()) {
      m.error("type", "unknown initial stress type '" + s.type + "'; allowed: geostatic, constant");
    }
    out.push_back(std::move(s));
  }
  return out;
}

std::vector<InterfaceSpec> read_interfaces(const YamlMap& top, const std::string& kinematics,
                                           const SchemaIndex& laws) {
  std::vector<InterfaceSpec> out;
  UniqueNames names("interface", "each interface needs its own, for its output files "
                                 "interface_<name>.csv and interface_<name>.pvd");
  const auto entries = list_entries(
      top, "interfaces",
      {"name", "between", "facet_sets", "obstacle", "law", "parameters", "initial_gap", "pairing"},
      "expected a list of {name, between | facet_sets, law, parameters}");
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const YamlMap& m = entries[i];
    if (!m.valid()) continue;
    InterfaceSpec spec;
    spec.where = m.where();
    spec.name = names.read(m, i);
    m.strings("between", spec.between);
    m.strings("facet_sets", spec.facet_sets);
    if (m.has("obstacle"))
      read_obstacle_interface(m, kinematics, spec);
    else if (m.has("between") == m.has("facet_sets"))
      m.error("between", "give exactly one of 'between: [region_a, region_b]' or "
                         "'facet_sets: [set_a, set_b]'");
    else if (m.has("between") && spec.between.size() != 2)
      m.error("between", "expected two region names [body 1, body 2]");
    else if (m.has("facet_sets") && spec.facet_sets.size() != 2)
      m.error("facet_sets", "expected two facet set names [body 1 side, body 2 side]");
    m.real("initial_gap", spec.initial_gap);
    if (m.string("pairing", spec.pairing) && m.has("pairing")) {
      if (spec.pairing != "coincident" && spec.pairing != "normal")
        m.error("pairing", "unknown pairing '" + spec.pairing + "'; expected coincident or normal");
      else if (!m.has("facet_sets"))
        m.error("pairing", "only facet_sets interfaces are paired this way (between: [a, b] "
                           "splits a conforming mesh, whose nodes coincide)");
    }
    if (m.string("law", spec.law, true) && m.has("law")) {
      if (!laws.contains(spec.law)) {
        m.error("law", laws.unknown_message(spec.law));
        continue;
      }
      if (m.has("parameters"))
        spec.parameters = read_parameters(m, "parameters", laws.schema(spec.law), {});
      else {
        const auto problems = validate(laws.schema(spec.law), spec.parameters);
        for (const auto& p : problems)
          m.error("law", "parameters." + p.key + ": " + p.message);
      }
    }
    out.push_back(std::move(spec));
  }
  return out;
}

ContactSolverSpec read_contact_solver(const YamlMap& top, const SchemaIndex& solvers) {
  ContactSolverSpec spec;
  const YAML::Node node = top.node("contact_solver");
  spec.where = top.where("contact_solver");
  if (!node.IsMap() || !node["type"]) {
    top.error("contact_solver",
              "expected {type: <solver>, ...}; registered solvers: " + join_names(solvers.names()));
    return spec;
  }
  spec.type = node["type"].Scalar();
  if (!solvers.contains(spec.type)) {
    top.diag().error(node["type"], "contact_solver.type", solvers.unknown_message(spec.type));
    return spec;
  }
  spec.parameters =
      read_parameters_node(node, "contact_solver", top.diag(), solvers.schema(spec.type), {"type"});
  return spec;
}

OutputSpec read_output(const YamlMap& top) {
  OutputSpec out;
  YamlMap m(top.node("output"), "output", top.diag(), {"directory", "vtk", "every", "checkpoint"});
  if (!m.valid()) return out;
  if (m.string("directory", out.directory)) out.where = m.where("directory");
  m.boolean("vtk", out.vtk);
  if (m.integer("every", out.every) && out.every < 1)
    m.error("every", "value " + std::to_string(out.every) + " is out of range [1, inf)");
  read_checkpoint(m, out);
  return out;
}

} // namespace bipot::input
