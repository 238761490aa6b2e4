// The $Nodes and $Elements sections of gmsh MSH 2.x files, ASCII and binary
// (see msh_elements.h). In ASCII files each element line must hold exactly
// 3 + tags + nodes values; a line that disagrees is refused rather than realigned.

#include <vector>

#include "ergo/mesh/input_error.h"
#include "ergo/mesh/msh_elements.h"
#include "ergo/mesh/read_support.h"

namespace ergo::msh {

namespace {

const char kReexportMsh22[] =
    "re-export the mesh with gmsh (gmsh FILE -0 -format msh22 -o OUT.msh)";

int64_t ReadCount(TextReader& reader, const std::string& what) {
  std::vector<std::string_view> tokens;
  if (!reader.NextTokens('\0', &tokens)) {
    reader.Fail("the file ends before the " + what, "the file is truncated: re-export it");
  }
  if (tokens.size() != 1) {
    reader.Fail("expected the " + what + " alone on the line, found " +
                    std::to_string(tokens.size()) + " values",
                kReexportMsh22);
  }
  return ParseInteger(reader, tokens[0], what);
}

}  // namespace

void ReadNodesV2(TextReader& reader, Collector* collector) {
  const int64_t count = ReadCount(reader, "node count");
  RequireCountFits(reader.path(), reader.Location(), "nodes", count, 8, reader.remaining_bytes());
  collector->ReserveNodes(count);
  std::vector<std::string_view> tokens;
  for (int64_t n = 0; n < count; ++n) {
    if (!reader.NextTokens('\0', &tokens)) {
      reader.Fail(
          "the file ends after " + std::to_string(n) + " of " + std::to_string(count) + " nodes",
          "the file is truncated: re-export it");
    }
    if (tokens.size() != 4) {
      reader.Fail(
          "a node line must be 'tag x y z', found " + std::to_string(tokens.size()) + " values",
          kReexportMsh22);
    }
    const int64_t tag = ParseInteger(reader, tokens[0], "node tag");
    const double x = ParseCoordinate(reader, tokens[1], tag);
    const double y = ParseCoordinate(reader, tokens[2], tag);
    const double z = ParseCoordinate(reader, tokens[3], tag);
    collector->AddNode(tag, x, y, z, reader.line_number(), reader.Location());
  }
  ExpectSectionEnd(reader, "$EndNodes", "the node count is wrong");
}

void ReadElementsV2(TextReader& reader, Collector* collector) {
  const int64_t count = ReadCount(reader, "element count");
  RequireCountFits(reader.path(), reader.Location(), "elements", count, 8,
                   reader.remaining_bytes());
  std::vector<std::string_view> tokens;
  std::vector<int64_t> nodes;
  for (int64_t e = 0; e < count; ++e) {
    if (!reader.NextTokens('\0', &tokens)) {
      reader.Fail(
          "the file ends after " + std::to_string(e) + " of " + std::to_string(count) + " elements",
          "the file is truncated: re-export it");
    }
    if (tokens.size() < 3) {
      reader.Fail("an element line needs at least 'number type tag-count', found " +
                      std::to_string(tokens.size()) + " values",
                  kReexportMsh22);
    }
    const int64_t number = ParseInteger(reader, tokens[0], "element number");
    const int64_t type = ParseInteger(reader, tokens[1], "element type");
    const int64_t tag_count = ParseInteger(reader, tokens[2], "element tag count");
    const std::string element = "element " + std::to_string(number);
    if (type <= 0 || type > 1000)
      reader.Fail(element + " has invalid type " + std::to_string(type), kReexportMsh22);
    if (tag_count < 0 || tag_count > static_cast<int64_t>(tokens.size()) - 3) {
      reader.Fail(element + " declares " + std::to_string(tag_count) + " tags but the line has " +
                      std::to_string(tokens.size()) + " values",
                  kReexportMsh22);
    }
    const int node_count = NodesPerElement(static_cast<int>(type));
    if (node_count < 0) {
      collector->CountUnknown(static_cast<int>(type), 1);
      continue;
    }
    const int64_t expected = 3 + tag_count + node_count;
    if (static_cast<int64_t>(tokens.size()) != expected) {
      reader.Fail(element + " (gmsh type " + std::to_string(type) + ", " +
                      std::to_string(node_count) + " nodes, " + std::to_string(tag_count) +
                      " tags) should have " + std::to_string(expected) +
                      " values on its line but has " + std::to_string(tokens.size()),
                  "the file does not follow the MSH 2 format; " + std::string(kReexportMsh22));
    }
    nodes.clear();
    for (int k = 0; k < node_count; ++k) {
      nodes.push_back(ParseInteger(reader, tokens[3 + tag_count + k], "node tag"));
    }
    collector->AddElement(static_cast<int>(type), nodes.data(), node_count, reader.line_number(),
                          reader.Location() + " (" + element + ")");
  }
  ExpectSectionEnd(reader, "$EndElements", "the element count is wrong");
}

void ReadNodesV2Binary(TextReader& reader, ByteOrder order, Collector* collector) {
  const int64_t count = ReadCount(reader, "node count");
  constexpr uint64_t kNodeBytes = 4 + 3 * 8;
  RequireCountFits(reader.path(), reader.Location(), "nodes", count, kNodeBytes,
                   reader.remaining_bytes());
  collector->ReserveNodes(count);
  ByteReader bytes(reader.text(), reader.offset(), order);
  for (int64_t n = 0; n < count; ++n) {
    int32_t tag = 0;
    double xyz[3];
    bytes.ReadInt32(&tag);  // sizes were checked above
    for (double& value : xyz) bytes.ReadFloat64(&value);
    collector->AddNode(tag, xyz[0], xyz[1], xyz[2], 0, "node " + std::to_string(tag));
  }
  reader.Seek(bytes.offset());
  ExpectSectionEnd(reader, "$EndNodes", "the node count is wrong");
}

void ReadElementsV2Binary(TextReader& reader, ByteOrder order, Collector* collector) {
  const int64_t count = ReadCount(reader, "element count");
  RequireCountFits(reader.path(), reader.Location(), "elements", count, 4 * 3,
                   reader.remaining_bytes());
  ByteReader bytes(reader.text(), reader.offset(), order);
  const std::string& path = reader.path();
  std::vector<int32_t> values;
  std::vector<int64_t> nodes;
  int64_t read = 0;
  while (read < count) {
    int32_t header[3];  // type, elements that follow, tags per element
    for (int32_t& value : header) {
      if (!bytes.ReadInt32(&value)) {
        throw InputError(path, "element " + std::to_string(read + 1),
                         "the file ends inside the binary $Elements section",
                         "the file is truncated: re-export it");
      }
    }
    const int node_count = NodesPerElement(header[0]);
    const std::string location = "element " + std::to_string(read + 1);
    if (node_count < 0) {
      throw InputError(path, location,
                       "binary element block of gmsh type " + std::to_string(header[0]) +
                           ", which ergo does not know (so it cannot skip it)",
                       "re-export as ASCII: gmsh FILE -0 -format msh41 -o OUT.msh");
    }
    if (header[1] <= 0 || header[1] > count - read || header[2] < 0 || header[2] > 1000) {
      throw InputError(path, location,
                       "binary element block header is invalid (" + std::to_string(header[1]) +
                           " elements with " + std::to_string(header[2]) + " tags)",
                       "the file is damaged: re-export it");
    }
    const int per_element = 1 + header[2] + node_count;
    RequireCountFits(path, location, "elements in a binary block", header[1],
                     4 * static_cast<uint64_t>(per_element), bytes.remaining());
    values.resize(static_cast<size_t>(per_element));
    nodes.resize(static_cast<size_t>(node_count));
    for (int32_t e = 0; e < header[1]; ++e) {
      for (int32_t& value : values) bytes.ReadInt32(&value);
      for (int k = 0; k < node_count; ++k) nodes[k] = values[1 + header[2] + k];
      collector->AddElement(header[0], nodes.data(), node_count, 0,
                            "element " + std::to_string(values[0]));
    }
    read += header[1];
  }
  reader.Seek(bytes.offset());
  ExpectSectionEnd(reader, "$EndElements", "the element count is wrong");
}

}  // namespace ergo::msh
