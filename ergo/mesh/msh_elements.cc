#include "ergo/mesh/msh_elements.h"

#include <algorithm>
#include <utility>

#include "ergo/mesh/input_error.h"
#include "ergo/mesh/read_support.h"

namespace ergo::msh {

namespace {

enum class Family { kPoint, kLine, kTriangle, kQuad, kTet, kHex, kPrism, kPyramid, kUnknown };

// gmsh element types 1-31 and the two high-order hexahedra (gmsh manual, "MSH file format").
struct TypeInfo {
  int type;
  int nodes;
  Family family;
};
constexpr TypeInfo kTypes[] = {
    {1, 2, Family::kLine},       {2, 3, Family::kTriangle},   {3, 4, Family::kQuad},
    {4, 4, Family::kTet},        {5, 8, Family::kHex},        {6, 6, Family::kPrism},
    {7, 5, Family::kPyramid},    {8, 3, Family::kLine},       {9, 6, Family::kTriangle},
    {10, 9, Family::kQuad},      {11, 10, Family::kTet},      {12, 27, Family::kHex},
    {13, 18, Family::kPrism},    {14, 14, Family::kPyramid},  {15, 1, Family::kPoint},
    {16, 8, Family::kQuad},      {17, 20, Family::kHex},      {18, 15, Family::kPrism},
    {19, 13, Family::kPyramid},  {20, 9, Family::kTriangle},  {21, 10, Family::kTriangle},
    {22, 12, Family::kTriangle}, {23, 15, Family::kTriangle}, {24, 15, Family::kTriangle},
    {25, 21, Family::kTriangle}, {26, 4, Family::kLine},      {27, 5, Family::kLine},
    {28, 6, Family::kLine},      {29, 20, Family::kTet},      {30, 35, Family::kTet},
    {31, 56, Family::kTet},      {92, 64, Family::kHex},      {93, 125, Family::kHex}};

const TypeInfo* Find(int type) {
  for (const TypeInfo& info : kTypes) {
    if (info.type == type) return &info;
  }
  return nullptr;
}

Family FamilyOf(int type) {
  const TypeInfo* info = Find(type);
  return info ? info->family : Family::kUnknown;
}

std::string TypeName(int type) {
  const TypeInfo* info = Find(type);
  if (!info) return "type-" + std::to_string(type) + " element";
  const char* family = "";
  switch (info->family) {
    case Family::kPoint:
      return "point";
    case Family::kLine:
      family = "line";
      break;
    case Family::kTriangle:
      family = "triangle";
      break;
    case Family::kQuad:
      family = "quad";
      break;
    case Family::kTet:
      family = "tet";
      break;
    case Family::kHex:
      family = "hexahedron";
      break;
    case Family::kPrism:
      family = "prism";
      break;
    case Family::kPyramid:
      family = "pyramid";
      break;
    case Family::kUnknown:
      break;
  }
  return std::to_string(info->nodes) + "-node " + family;
}

bool IsLinear(int type) { return type == 2 || type == 3 || type == 4; }

}  // namespace

int NodesPerElement(int type) {
  const TypeInfo* info = Find(type);
  return info ? info->nodes : -1;
}

void Collector::ReserveNodes(int64_t count) {
  xyz_.reserve(xyz_.size() + static_cast<size_t>(3 * count));
  index_of_tag_.reserve(index_of_tag_.size() + static_cast<size_t>(count));
}

void Collector::AddNode(int64_t tag, double x, double y, double z, int line,
                        const std::string& location) {
  // gmsh numbers nodes from 1, but some writers start at 0; only negative tags are wrong.
  if (tag < 0) {
    throw InputError(path_, location, "node tag " + std::to_string(tag) + " is negative",
                     "gmsh node tags are positive: re-export the mesh");
  }
  RequireFinite(path_, location, tag, x, y, z);
  const auto [it, inserted] = index_of_tag_.emplace(tag, static_cast<int>(node_count()));
  if (!inserted) {
    throw InputError(path_, location, "node tag " + std::to_string(tag) + " appears twice",
                     "re-export the mesh; every node needs its own tag");
  }
  xyz_.insert(xyz_.end(), {x, y, z});
  node_lines_.push_back(line);
}

int Collector::NodeIndex(int64_t tag, const std::string& location) const {
  const auto it = index_of_tag_.find(tag);
  if (it == index_of_tag_.end()) {
    throw InputError(path_, location,
                     "element refers to node " + std::to_string(tag) +
                         ", which the $Nodes section does not define",
                     "re-export the mesh; every element node must be defined in $Nodes");
  }
  return it->second;
}

void Collector::AddElement(int type, const int64_t* node_tags, int node_count, int line,
                           const std::string& location) {
  const Family family = FamilyOf(type);
  if (family == Family::kUnknown) {
    CountUnknown(type, 1);
    return;
  }
  ++count_by_type_[static_cast<size_t>(type)];  // known types are all below 100
  int corners[4];
  const int corner_count = family == Family::kTet || family == Family::kQuad ? 4
                           : family == Family::kTriangle                     ? 3
                                                                             : 0;
  // Every node must exist, even of elements that are not kept: a dangling tag means a
  // broken file.
  for (int k = 0; k < node_count; ++k) {
    const int index = NodeIndex(node_tags[k], location);
    if (k < corner_count) corners[k] = index;
  }
  if (family == Family::kTet) {
    tets_.insert(tets_.end(), corners, corners + 4);
    tet_lines_.push_back(line);
  } else if (family == Family::kTriangle) {
    triangles_.insert(triangles_.end(), corners, corners + 3);
    triangle_lines_.push_back(line);
  } else if (family == Family::kQuad) {
    triangles_.insert(triangles_.end(),
                      {corners[0], corners[1], corners[2], corners[0], corners[2], corners[3]});
    triangle_lines_.insert(triangle_lines_.end(), {line, line});
  }
}

void Collector::CountUnknown(int type, int64_t count) {
  if (unknown_elements_ == 0) first_unknown_type_ = type;
  unknown_elements_ += count;
}

AnyMesh Collector::Finish(const ReadOptions& options, MshContent want, const std::string& format,
                          ReadDetails* details) {
  const bool use_tets =
      want == MshContent::kTets || (want == MshContent::kTetsElseTriangles && !tets_.empty());
  const std::vector<int>& elements = use_tets ? tets_ : triangles_;
  const std::vector<int>& element_lines = use_tets ? tet_lines_ : triangle_lines_;
  const int corners = use_tets ? 4 : 3;
  if (use_tets && tets_.empty()) {
    throw InputError(path_, "",
                     "the file has no tetrahedra" +
                         std::string(triangles_.empty() ? "" : " (it is a surface mesh)") + " (" +
                         format + ")",
                     "mesh the volume in gmsh (Mesh > 3D, or gmsh FILE -3) and save it again");
  }
  if (elements.empty()) {
    throw InputError(path_, "",
                     "the file has " + std::to_string(node_count()) +
                         " nodes but no triangles, quads or tetrahedra (" + format + ")",
                     "mesh the surface or the volume in gmsh and save it again");
  }
  // Keep only the nodes the kept elements use, in file order.
  std::vector<int> new_index(static_cast<size_t>(node_count()), -1);
  for (int node : elements) new_index[static_cast<size_t>(node)] = 0;
  int kept = 0;
  for (int& index : new_index) {
    if (index == 0) index = kept++;
  }
  Vertices vertices(kept, 3);
  std::vector<int> vertex_lines;
  vertex_lines.reserve(static_cast<size_t>(kept));
  for (int64_t node = 0; node < node_count(); ++node) {
    const int index = new_index[static_cast<size_t>(node)];
    if (index < 0) continue;
    vertices.row(index) << xyz_[3 * node], xyz_[3 * node + 1], xyz_[3 * node + 2];
    vertex_lines.push_back(node_lines_[static_cast<size_t>(node)]);
  }
  ScaleToMetres(options, &vertices);
  const Eigen::Index element_count = static_cast<Eigen::Index>(elements.size()) / corners;
  AnyMesh mesh;
  mesh.is_tet = use_tets;
  if (use_tets) {
    mesh.volume.vertices = std::move(vertices);
    mesh.volume.tets.resize(element_count, 4);
    for (Eigen::Index t = 0; t < element_count; ++t) {
      for (int k = 0; k < 4; ++k) mesh.volume.tets(t, k) = new_index[elements[4 * t + k]];
    }
  } else {
    mesh.surface.vertices = std::move(vertices);
    mesh.surface.triangles.resize(element_count, 3);
    for (Eigen::Index t = 0; t < element_count; ++t) {
      for (int k = 0; k < 3; ++k) mesh.surface.triangles(t, k) = new_index[elements[3 * t + k]];
    }
  }
  if (!details) return mesh;
  details->format = format;
  if (element_lines.size() == static_cast<size_t>(element_count) &&
      std::all_of(element_lines.begin(), element_lines.end(), [](int l) { return l > 0; })) {
    details->element_lines = element_lines;
    details->vertex_lines = std::move(vertex_lines);
  }
  std::string higher_order, ignored;
  int64_t quads = 0;
  for (size_t type = 0; type < count_by_type_.size(); ++type) {
    const int64_t count = count_by_type_[type];
    if (count == 0) continue;
    const Family family = FamilyOf(static_cast<int>(type));
    const bool kept_family = use_tets ? family == Family::kTet
                                      : (family == Family::kTriangle || family == Family::kQuad);
    const std::string entry =
        std::to_string(count) + " " + TypeName(static_cast<int>(type)) + (count == 1 ? "" : "s");
    if (!kept_family) {
      ignored += (ignored.empty() ? "" : ", ") + entry;
    } else if (!IsLinear(static_cast<int>(type))) {
      higher_order += (higher_order.empty() ? "" : ", ") + entry;
    }
    if (kept_family && family == Family::kQuad) quads += count;
  }
  if (!higher_order.empty()) {
    AddNote(details, false, "",
            higher_order + ": only their corner nodes are used (ergo's elements are linear)");
  }
  if (quads > 0) {
    AddNote(details, false, "",
            Counted(quads, "quad was", "quads were") + " split into two triangles");
  }
  if (!ignored.empty()) {
    AddNote(details, false, "",
            "ignored " + ignored + " (ergo uses the " +
                (use_tets ? "tetrahedra" : "triangles and quads") + ")");
  }
  if (unknown_elements_ > 0) {
    AddNote(details, false, "",
            "ignored " + Counted(unknown_elements_, "element", "elements") +
                " of types ergo does not know (first: type " + std::to_string(first_unknown_type_) +
                ")");
  }
  if (kept < node_count()) {
    AddNote(details, false, "",
            Counted(node_count() - kept, "node", "nodes") + " used by no " +
                (use_tets ? "tetrahedron" : "triangle") + " dropped");
  }
  return mesh;
}

void ExpectSectionEnd(TextReader& reader, const std::string& end_tag, const std::string& why) {
  std::vector<std::string_view> tokens;
  if (!reader.NextTokens('\0', &tokens)) {
    reader.Fail("the file ends before " + end_tag, "the file is truncated: re-export it");
  }
  if (tokens.size() != 1 || tokens[0] != end_tag) {
    reader.Fail("expected " + end_tag + " but found " + Quote(tokens[0]) + ": " + why,
                "re-export the mesh with gmsh (-format msh41 or msh22)");
  }
}

}  // namespace ergo::msh
