// The $Nodes and $Elements sections of gmsh MSH 4.0 and 4.1 ASCII files (see
// msh_elements.h). Both group nodes and elements in entity blocks; 4.1 lists a block's
// node tags before its coordinates and orders block headers (dim, tag, ...), 4.0 writes
// "tag x y z" lines and orders block headers (tag, dim, ...).

#include <vector>

#include "ergo/mesh/input_error.h"
#include "ergo/mesh/msh_elements.h"
#include "ergo/mesh/read_support.h"

namespace ergo::msh {

namespace {

const char kReexportMsh41[] =
    "re-export the mesh with gmsh (gmsh FILE -0 -format msh41 -o OUT.msh)";

// Reads a line of `count` integers (at least min_count); returns them.
std::vector<int64_t> ReadIntegers(TextReader& reader, size_t min_count, size_t max_count,
                                  const std::string& what) {
  std::vector<std::string_view> tokens;
  if (!reader.NextTokens('\0', &tokens)) {
    reader.Fail("the file ends before the " + what, "the file is truncated: re-export it");
  }
  if (tokens.size() < min_count || tokens.size() > max_count) {
    reader.Fail("the " + what + " line should have " + std::to_string(min_count) +
                    (max_count > min_count ? " or more" : "") + " values, found " +
                    std::to_string(tokens.size()),
                kReexportMsh41);
  }
  std::vector<int64_t> values;
  for (std::string_view token : tokens) values.push_back(ParseInteger(reader, token, what));
  return values;
}

}  // namespace

void ReadNodesV4(TextReader& reader, bool v41, Collector* collector) {
  const std::vector<int64_t> header =
      ReadIntegers(reader, v41 ? 4 : 2, v41 ? 4 : 2, "$Nodes header");
  const int64_t blocks = header[0], total = header[1];
  const std::string& path = reader.path();
  RequireCountFits(path, reader.Location(), "node blocks", blocks, 8, reader.remaining_bytes());
  RequireCountFits(path, reader.Location(), "nodes", total, 8, reader.remaining_bytes());
  collector->ReserveNodes(total);
  std::vector<std::string_view> tokens;
  std::vector<int64_t> tags;
  std::vector<int> tag_lines;
  int64_t read = 0;
  for (int64_t b = 0; b < blocks; ++b) {
    const std::vector<int64_t> block = ReadIntegers(reader, 4, 4, "node block header");
    const int64_t dim = v41 ? block[0] : block[1];
    const bool parametric = block[2] != 0;
    const int64_t in_block = block[3];
    if (in_block < 0 || in_block > total - read) {
      reader.Fail("node block declares " + std::to_string(in_block) + " nodes, but only " +
                      std::to_string(total - read) + " of the header's total remain",
                  kReexportMsh41);
    }
    // Coordinates, then the parametric coordinates of nodes on curves and surfaces.
    const size_t values = 3 + (parametric ? static_cast<size_t>(dim < 0 ? 0 : dim) : 0);
    if (v41) {
      tags.clear();
      tag_lines.clear();
      for (int64_t n = 0; n < in_block; ++n) {
        tags.push_back(ReadIntegers(reader, 1, 1, "node tag")[0]);
      }
      for (int64_t n = 0; n < in_block; ++n) {
        if (!reader.NextTokens('\0', &tokens)) {
          reader.Fail("the file ends inside a node block", "the file is truncated: re-export it");
        }
        if (tokens.size() != values) {
          reader.Fail("node coordinates line should have " + std::to_string(values) +
                          " values, found " + std::to_string(tokens.size()),
                      kReexportMsh41);
        }
        const int64_t tag = tags[static_cast<size_t>(n)];
        const double x = ParseCoordinate(reader, tokens[0], tag);
        const double y = ParseCoordinate(reader, tokens[1], tag);
        const double z = ParseCoordinate(reader, tokens[2], tag);
        collector->AddNode(tag, x, y, z, reader.line_number(), reader.Location());
      }
    } else {
      for (int64_t n = 0; n < in_block; ++n) {
        if (!reader.NextTokens('\0', &tokens)) {
          reader.Fail("the file ends inside a node block", "the file is truncated: re-export it");
        }
        if (tokens.size() != values + 1) {
          reader.Fail("node line should have " + std::to_string(values + 1) + " values (tag x y z" +
                          (values > 3 ? " u..." : "") + "), found " + std::to_string(tokens.size()),
                      kReexportMsh41);
        }
        const int64_t tag = ParseInteger(reader, tokens[0], "node tag");
        const double x = ParseCoordinate(reader, tokens[1], tag);
        const double y = ParseCoordinate(reader, tokens[2], tag);
        const double z = ParseCoordinate(reader, tokens[3], tag);
        collector->AddNode(tag, x, y, z, reader.line_number(), reader.Location());
      }
    }
    read += in_block;
  }
  if (read != total) {
    reader.Fail("the $Nodes header declares " + std::to_string(total) +
                    " nodes but its blocks hold " + std::to_string(read),
                kReexportMsh41);
  }
  ExpectSectionEnd(reader, "$EndNodes", "the node counts are wrong");
}

void ReadElementsV4(TextReader& reader, bool v41, Collector* collector) {
  const std::vector<int64_t> header =
      ReadIntegers(reader, v41 ? 4 : 2, v41 ? 4 : 2, "$Elements header");
  const int64_t blocks = header[0], total = header[1];
  const std::string& path = reader.path();
  RequireCountFits(path, reader.Location(), "element blocks", blocks, 8, reader.remaining_bytes());
  RequireCountFits(path, reader.Location(), "elements", total, 2, reader.remaining_bytes());
  std::vector<std::string_view> tokens;
  std::vector<int64_t> nodes;
  int64_t read = 0;
  for (int64_t b = 0; b < blocks; ++b) {
    const std::vector<int64_t> block = ReadIntegers(reader, 4, 4, "element block header");
    const int64_t type = block[2], in_block = block[3];
    if (in_block < 0 || in_block > total - read) {
      reader.Fail("element block declares " + std::to_string(in_block) + " elements, but only " +
                      std::to_string(total - read) + " of the header's total remain",
                  kReexportMsh41);
    }
    const int node_count = NodesPerElement(static_cast<int>(type > 0 && type < 1000 ? type : 0));
    for (int64_t e = 0; e < in_block; ++e) {
      if (!reader.NextTokens('\0', &tokens)) {
        reader.Fail("the file ends inside an element block", "the file is truncated: re-export it");
      }
      if (node_count < 0) continue;  // an unknown type: one element per line, skipped
      if (tokens.size() != static_cast<size_t>(node_count) + 1) {
        reader.Fail("element line of gmsh type " + std::to_string(type) + " should have " +
                        std::to_string(node_count + 1) + " values (tag and " +
                        std::to_string(node_count) + " nodes), found " +
                        std::to_string(tokens.size()),
                    kReexportMsh41);
      }
      const int64_t tag = ParseInteger(reader, tokens[0], "element tag");
      nodes.clear();
      for (int k = 0; k < node_count; ++k) {
        nodes.push_back(ParseInteger(reader, tokens[1 + k], "node tag"));
      }
      collector->AddElement(static_cast<int>(type), nodes.data(), node_count, reader.line_number(),
                            reader.Location() + " (element " + std::to_string(tag) + ")");
    }
    if (node_count < 0) collector->CountUnknown(static_cast<int>(type), in_block);
    read += in_block;
  }
  if (read != total) {
    reader.Fail("the $Elements header declares " + std::to_string(total) +
                    " elements but its blocks hold " + std::to_string(read),
                kReexportMsh41);
  }
  ExpectSectionEnd(reader, "$EndElements", "the element counts are wrong");
}

}  // namespace ergo::msh
