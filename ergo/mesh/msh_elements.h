// Internal to the gmsh reader: the gmsh element-type table (node count of each type) and
// the collector that the version-specific section parsers (msh2_format.cc,
// msh4_format.cc) feed with nodes and elements. It maps node tags to indices, keeps
// tetrahedra and triangles (corners of higher-order elements, quads split), tallies
// everything else for notes, and builds the mesh in metres.
#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "ergo/mesh/binary_reader.h"
#include "ergo/mesh/mesh_io.h"
#include "ergo/mesh/msh_format.h"
#include "ergo/mesh/text_reader.h"

namespace ergo::msh {

// Nodes of a gmsh element type, or -1 for a type ergo does not know.
int NodesPerElement(int type);

class Collector {
 public:
  explicit Collector(std::string path) : path_(std::move(path)) {}

  // Reserves room for `count` more nodes (the caller has bounded count by the file size).
  void ReserveNodes(int64_t count);
  // Adds a node; throws when the tag is negative or repeats an earlier node's tag.
  void AddNode(int64_t tag, double x, double y, double z, int line, const std::string& location);
  int64_t node_count() const { return static_cast<int64_t>(xyz_.size() / 3); }

  // Adds an element of gmsh `type` with its node tags (NodesPerElement(type) of them, or
  // any number for unknown types, which are only counted). Throws naming `location` when
  // a node tag is unknown.
  void AddElement(int type, const int64_t* node_tags, int node_count, int line,
                  const std::string& location);
  // Counts an element that was skipped without being read (unknown type in v4 blocks).
  void CountUnknown(int type, int64_t count);

  // The mesh in metres, nodes not used by the kept elements dropped.
  AnyMesh Finish(const ReadOptions& options, MshContent want, const std::string& format,
                 ReadDetails* details);

 private:
  int NodeIndex(int64_t tag, const std::string& location) const;

  std::string path_;
  std::vector<double> xyz_;
  std::vector<int> node_lines_;
  std::unordered_map<int64_t, int> index_of_tag_;
  std::vector<int> tets_, triangles_;
  std::vector<int> tet_lines_, triangle_lines_;
  std::vector<int64_t> count_by_type_ = std::vector<int64_t>(100, 0);
  int64_t unknown_elements_ = 0;
  int first_unknown_type_ = 0;
};

// Section parsers. Each starts after the section's opening line ($Nodes, $Elements) and
// consumes its closing line; all throw InputError naming the line on any inconsistency.
void ReadNodesV2(TextReader& reader, Collector* collector);
void ReadElementsV2(TextReader& reader, Collector* collector);
void ReadNodesV2Binary(TextReader& reader, ByteOrder order, Collector* collector);
void ReadElementsV2Binary(TextReader& reader, ByteOrder order, Collector* collector);
void ReadNodesV4(TextReader& reader, bool v41, Collector* collector);
void ReadElementsV4(TextReader& reader, bool v41, Collector* collector);

// Reads lines up to the next non-blank one and throws unless it is `end_tag`.
void ExpectSectionEnd(TextReader& reader, const std::string& end_tag, const std::string& why);

}  // namespace ergo::msh
