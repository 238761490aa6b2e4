#include "ergo/mesh/ply_format.h"

#include <cmath>
#include <cstring>
#include <string_view>
#include <vector>

#include "ergo/mesh/atomic_file.h"
#include "ergo/mesh/binary_reader.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/read_support.h"
#include "ergo/mesh/text_reader.h"

namespace ergo {

namespace {

enum class PlyType { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };

bool ParsePlyType(std::string_view name, PlyType* type) {
  static const struct {
    const char* name;
    PlyType type;
  } kNames[] = {
      {"char", PlyType::kInt8},      {"int8", PlyType::kInt8},       {"uchar", PlyType::kUint8},
      {"uint8", PlyType::kUint8},    {"short", PlyType::kInt16},     {"int16", PlyType::kInt16},
      {"ushort", PlyType::kUint16},  {"uint16", PlyType::kUint16},   {"int", PlyType::kInt32},
      {"int32", PlyType::kInt32},    {"uint", PlyType::kUint32},     {"uint32", PlyType::kUint32},
      {"float", PlyType::kFloat32},  {"float32", PlyType::kFloat32}, {"double", PlyType::kFloat64},
      {"float64", PlyType::kFloat64}};
  for (const auto& entry : kNames) {
    if (name == entry.name) {
      *type = entry.type;
      return true;
    }
  }
  return false;
}

int TypeSize(PlyType type) {
  switch (type) {
    case PlyType::kInt8:
    case PlyType::kUint8:
      return 1;
    case PlyType::kInt16:
    case PlyType::kUint16:
      return 2;
    case PlyType::kInt32:
    case PlyType::kUint32:
    case PlyType::kFloat32:
      return 4;
    case PlyType::kFloat64:
      return 8;
  }
  return 1;
}

bool IsIntegerType(PlyType type) { return type != PlyType::kFloat32 && type != PlyType::kFloat64; }

struct PlyProperty {
  std::string name;
  bool is_list = false;
  PlyType count_type = PlyType::kUint8;
  PlyType type = PlyType::kFloat32;
};

struct PlyElement {
  std::string name;
  int64_t count = 0;
  int line = 0;
  std::vector<PlyProperty> properties;
};

enum class PlyEncoding { kAscii, kBinaryLittleEndian, kBinaryBigEndian };

struct PlyHeader {
  PlyEncoding encoding = PlyEncoding::kAscii;
  std::vector<PlyElement> elements;
  int unknown_lines = 0;  // header lines that are not PLY keywords (ignored)
  std::string first_unknown;
};

const char* EncodingName(PlyEncoding encoding) {
  switch (encoding) {
    case PlyEncoding::kAscii:
      return "PLY ASCII";
    case PlyEncoding::kBinaryLittleEndian:
      return "PLY binary little-endian";
    case PlyEncoding::kBinaryBigEndian:
      return "PLY binary big-endian";
  }
  return "PLY";
}

// Reads the header up to and including the end_header line; leaves `reader` after it.
PlyHeader ReadPlyHeader(TextReader& reader) {
  const std::string fix = "re-export the mesh as PLY; its header is damaged";
  PlyHeader header;
  bool have_format = false;
  std::vector<std::string_view> tokens;
  std::string_view line;
  try {
    if (!reader.NextLine(&line)) reader.Fail("the file is empty", fix);
    reader.RequireRecordLength(line);
    if (line.substr(0, 3) == "\xEF\xBB\xBF") line.remove_prefix(3);
    SplitTokens(line, '\0', &tokens);
    if (tokens.size() != 1 || tokens[0] != "ply") {
      reader.Fail("not a PLY file: the first line is " + Quote(line) + ", not 'ply'",
                  "check the file's format");
    }
    while (true) {
      if (!reader.NextLine(&line)) {
        reader.Fail("the header has no 'end_header' line", fix);
      }
      reader.RequireRecordLength(line);
      SplitTokens(line, '\0', &tokens);
      if (tokens.empty()) continue;
      const std::string_view keyword = tokens[0];
      if (keyword == "end_header") break;
      if (keyword == "comment" || keyword == "obj_info") continue;
      if (keyword == "format") {
        if (tokens.size() < 2) reader.Fail("the format line names no format", fix);
        if (tokens[1] == "ascii") {
          header.encoding = PlyEncoding::kAscii;
        } else if (tokens[1] == "binary_little_endian") {
          header.encoding = PlyEncoding::kBinaryLittleEndian;
        } else if (tokens[1] == "binary_big_endian") {
          header.encoding = PlyEncoding::kBinaryBigEndian;
        } else {
          reader.Fail("unknown PLY format " + Quote(tokens[1]),
                      "use ascii, binary_little_endian or binary_big_endian");
        }
        have_format = true;
      } else if (keyword == "element") {
        if (tokens.size() != 3) reader.Fail("an element line must be 'element NAME COUNT'", fix);
        PlyElement element;
        element.name = std::string(tokens[1]);
        element.count = ParseInteger(reader, tokens[2], "count of element '" + element.name + "'");
        element.line = reader.line_number();
        if (element.count < 0) {
          reader.Fail("element '" + element.name + "' has a negative count", fix);
        }
        header.elements.push_back(std::move(element));
      } else if (keyword == "property") {
        if (header.elements.empty()) reader.Fail("a property comes before any element", fix);
        PlyProperty property;
        bool known = false;
        if (tokens.size() == 5 && tokens[1] == "list") {
          property.is_list = true;
          known = ParsePlyType(tokens[2], &property.count_type) &&
                  ParsePlyType(tokens[3], &property.type);
          property.name = std::string(tokens[4]);
          if (known && !IsIntegerType(property.count_type)) {
            reader.Fail("list '" + property.name + "' has a non-integer count type", fix);
          }
        } else if (tokens.size() == 3) {
          known = ParsePlyType(tokens[1], &property.type);
          property.name = std::string(tokens[2]);
        }
        if (!known) reader.Fail("cannot understand the property line " + Quote(line), fix);
        header.elements.back().properties.push_back(std::move(property));
      } else if (header.unknown_lines++ == 0) {
        header.first_unknown = reader.Location() + " " + Quote(line);
      }
    }
  } catch (const InputError& error) {
    // A NUL byte or an overlong line before end_header: say that the header is broken.
    if (error.problem().find("binary data") == std::string::npos &&
        error.problem().find("longer than") == std::string::npos) {
      throw;
    }
    throw InputError(reader.path(), error.location(),
                     "the PLY header is not terminated by 'end_header' before binary data",
                     "the file is damaged or not a PLY file: re-export it");
  }
  if (!have_format) reader.Fail("the header has no 'format' line", fix);
  return header;
}

// Record access for ASCII data: one record per line, values separated by whitespace.
class AsciiRecords {
 public:
  explicit AsciiRecords(TextReader* reader) : reader_(reader) {}
  void Begin(const PlyElement& element, int64_t record) {
    std::string_view line;
    do {
      if (!reader_->NextLine(&line)) {
        reader_->Fail("the file ends at record " + std::to_string(record) + " of the " +
                          std::to_string(element.count) + " '" + element.name +
                          "' records the header declares",
                      "the file is truncated or the header's count is wrong: re-export it");
      }
      tokens_ = LineTokens(line, '\0');
    } while (tokens_.AtEnd());
    values_ = 0;
  }
  double Value(PlyType type, const PlyElement& element, int64_t record) {
    std::string_view token;
    if (!tokens_.Next(&token)) {
      reader_->Fail("'" + element.name + "' record " + std::to_string(record) + " has only " +
                        std::to_string(values_) + " values, fewer than the header declares",
                    "the file does not match its header: re-export it");
    }
    ++values_;
    double value = 0;
    if (!ParseDouble(token, &value)) {
      reader_->Fail("value " + Quote(token) + " of '" + element.name + "' record " +
                        std::to_string(record) + " is not a number",
                    "the file does not match its header: re-export it");
    }
    return value;
  }
  // True when the record had more values than the header declares.
  bool End() const { return !tokens_.AtEnd(); }
  std::string Location(const PlyElement&, int64_t) const { return reader_->Location(); }
  int line() const { return reader_->line_number(); }
  // Bytes after the last value read (one line per record: a face's list may be long).
  uint64_t remaining() const { return tokens_.remaining_bytes() + reader_->remaining_bytes(); }

 private:
  TextReader* reader_;
  LineTokens tokens_;
  int64_t values_ = 0;
};

// Record access for binary data in either byte order.
class BinaryRecords {
 public:
  BinaryRecords(const std::string& path, ByteReader bytes) : path_(path), bytes_(bytes) {}
  void Begin(const PlyElement&, int64_t) {}
  double Value(PlyType type, const PlyElement& element, int64_t record) {
    uint64_t bits = 0;
    if (!bytes_.ReadUnsigned(TypeSize(type), &bits)) {
      throw InputError(path_, Location(element, record),
                       "the file ends inside '" + element.name + "' record " +
                           std::to_string(record) + " of " + std::to_string(element.count),
                       "the file is truncated: re-export it");
    }
    switch (type) {
      case PlyType::kInt8:
        return static_cast<int8_t>(bits);
      case PlyType::kUint8:
      case PlyType::kUint16:
      case PlyType::kUint32:
        return static_cast<double>(bits);
      case PlyType::kInt16:
        return static_cast<int16_t>(bits);
      case PlyType::kInt32:
        return static_cast<int32_t>(bits);
      case PlyType::kFloat32: {
        const uint32_t narrow = static_cast<uint32_t>(bits);
        float value;
        std::memcpy(&value, &narrow, 4);
        return value;
      }
      case PlyType::kFloat64: {
        double value;
        std::memcpy(&value, &bits, 8);
        return value;
      }
    }
    return 0;
  }
  bool End() const { return false; }
  std::string Location(const PlyElement& element, int64_t record) const {
    return element.name + " " + std::to_string(record);
  }
  int line() const { return 0; }
  uint64_t remaining() const { return bytes_.remaining(); }

 private:
  const std::string& path_;
  ByteReader bytes_;
};

// Fewest bytes one record of `element` can take (lists may be empty).
uint64_t MinRecordBytes(const PlyElement& element, bool ascii) {
  uint64_t bytes = 0;
  for (const PlyProperty& property : element.properties) {
    bytes += ascii ? 2 : TypeSize(property.is_list ? property.count_type : property.type);
  }
  return bytes;
}

int FindProperty(const PlyElement& element, std::string_view name, bool is_list) {
  for (size_t i = 0; i < element.properties.size(); ++i) {
    if (element.properties[i].name == name && element.properties[i].is_list == is_list) {
      return static_cast<int>(i);
    }
  }
  return -1;
}

// Reads every element's records from `records`; vertices and faces go to `builder`.
template <typename Records>
void ReadData(const std::string& path, const PlyHeader& header, int64_t vertex_count,
              Records& records, SurfaceBuilder* builder, ReadDetails* details) {
  const bool ascii = header.encoding == PlyEncoding::kAscii;
  int64_t long_records = 0;
  std::string first_long_record;
  std::vector<int> corners;
  for (const PlyElement& element : header.elements) {
    if (element.count > 0 && element.properties.empty()) {
      throw InputError(path, "line " + std::to_string(element.line),
                       "element '" + element.name + "' declares " + std::to_string(element.count) +
                           " records but no properties",
                       "re-export the mesh; its header is damaged");
    }
    RequireCountFits(path, "line " + std::to_string(element.line), "'" + element.name + "' records",
                     element.count, MinRecordBytes(element, ascii), records.remaining());
    const bool is_vertex = element.name == "vertex";
    const bool is_face = element.name == "face";
    int coordinate[3] = {-1, -1, -1};
    int indices = -1;
    if (is_vertex) {
      for (int k = 0; k < 3; ++k) {
        coordinate[k] = FindProperty(element, std::string(1, static_cast<char>('x' + k)), false);
      }
      if (coordinate[0] < 0 || coordinate[1] < 0 || coordinate[2] < 0) {
        throw InputError(path, "line " + std::to_string(element.line),
                         "element 'vertex' lacks one of the scalar properties x, y, z",
                         "re-export the mesh with vertex positions named x, y and z");
      }
      builder->Reserve(element.count, 0);
    }
    if (is_face) {
      indices = FindProperty(element, "vertex_indices", true);
      if (indices < 0) indices = FindProperty(element, "vertex_index", true);
      if (indices < 0) {
        throw InputError(path, "line " + std::to_string(element.line),
                         "element 'face' has no list property 'vertex_indices' or "
                         "'vertex_index'",
                         "re-export the mesh with faces as vertex index lists");
      }
    }
    for (int64_t record = 0; record < element.count; ++record) {
      records.Begin(element, record);
      double xyz[3] = {0, 0, 0};
      corners.clear();
      for (size_t p = 0; p < element.properties.size(); ++p) {
        const PlyProperty& property = element.properties[p];
        if (!property.is_list) {
          const double value = records.Value(property.type, element, record);
          for (int k = 0; k < 3; ++k) {
            if (coordinate[k] == static_cast<int>(p)) xyz[k] = value;
          }
          continue;
        }
        const double count = records.Value(property.count_type, element, record);
        if (!(count >= 0) || count != std::floor(count) ||
            count > static_cast<double>(records.remaining())) {
          throw InputError(path, records.Location(element, record),
                           "list '" + property.name + "' of '" + element.name + "' record " +
                               std::to_string(record) + " has an entry count of " +
                               std::to_string(count) +
                               ", which is not a count or exceeds what the file holds",
                           "the file is damaged: re-export it");
        }
        const bool keep = static_cast<int>(p) == indices;
        for (int64_t k = 0; k < static_cast<int64_t>(count); ++k) {
          const double value = records.Value(property.type, element, record);
          if (!keep) continue;
          if (value != std::floor(value) || !(std::fabs(value) < 2147483648.0)) {
            throw InputError(path, records.Location(element, record),
                             "face " + std::to_string(record) + " has a vertex index " +
                                 std::to_string(value) + " that is not an integer",
                             "re-export the mesh; face indices must be integers");
          }
          const int64_t index = static_cast<int64_t>(value);
          RequireVertexIndex(path, records.Location(element, record),
                             "face " + std::to_string(record), index, index, vertex_count);
          corners.push_back(static_cast<int>(index));
        }
      }
      if (records.End() && long_records++ == 0) {
        first_long_record = records.Location(element, record);
      }
      if (is_vertex) {
        RequireFinite(path, records.Location(element, record), record, xyz[0], xyz[1], xyz[2]);
        builder->AddVertex(xyz[0], xyz[1], xyz[2], records.line());
      } else if (is_face) {
        builder->AddPolygon(corners.data(), static_cast<int>(corners.size()), records.line(),
                            records.Location(element, record));
      }
    }
  }
  if (long_records > 0) {
    AddNote(details, true, first_long_record,
            Counted(long_records, "record has", "records have") +
                " more values than the header declares; the extra values were ignored",
            "the file does not match its header: re-export it");
  }
}

}  // namespace

TriMesh ReadPly(const std::string& path, const ReadOptions& options, ReadDetails* details) {
  const std::string bytes = ReadFileBytes(path);
  TextReader reader(path, bytes);
  const PlyHeader header = ReadPlyHeader(reader);
  const std::string format = EncodingName(header.encoding);
  int64_t vertex_count = 0;
  bool have_vertices = false;
  std::string ignored;
  for (const PlyElement& element : header.elements) {
    if (element.name == "vertex") {
      if (have_vertices) {
        throw InputError(path, "line " + std::to_string(element.line),
                         "the header declares element 'vertex' twice",
                         "re-export the mesh; its header is damaged");
      }
      have_vertices = true;
      vertex_count = element.count;
    } else if (element.name != "face" && element.count > 0) {
      ignored += (ignored.empty() ? "'" : ", '") + element.name + "'";
    }
  }
  SurfaceBuilder builder;
  if (header.encoding == PlyEncoding::kAscii) {
    AsciiRecords records(&reader);
    ReadData(path, header, vertex_count, records, &builder, details);
    std::vector<std::string_view> tokens;
    if (reader.NextTokens('\0', &tokens)) {
      AddNote(details, false, reader.Location(), "data after the last element was ignored");
    }
  } else {
    const ByteOrder order = header.encoding == PlyEncoding::kBinaryBigEndian
                                ? ByteOrder::kBigEndian
                                : ByteOrder::kLittleEndian;
    BinaryRecords records(path, ByteReader(bytes, reader.offset(), order));
    ReadData(path, header, vertex_count, records, &builder, details);
    if (records.remaining() > 0) {
      AddNote(details, false, "",
              std::to_string(records.remaining()) + " bytes after the last element were ignored");
    }
  }
  if (!ignored.empty()) {
    AddNote(details, false, "", "elements " + ignored + " were ignored");
  }
  if (header.unknown_lines > 0) {
    AddNote(details, true, "",
            Counted(header.unknown_lines, "header line is", "header lines are") +
                " not PLY and ignored (first: " + header.first_unknown + ")",
            "start free text in a PLY header with 'comment'");
  }
  return builder.Finish(path, options, format, details);
}

void WritePly(const std::string& path, const TriMesh& mesh, const WriteOptions& options) {
  const double metres_per_unit = MetresPerUnit(options.unit);
  const bool binary = options.encoding == Encoding::kBinary;
  WriteFileAtomically(path, [&](std::ostream& out) {
    out << "ply\nformat " << (binary ? "binary_little_endian" : "ascii") << " 1.0\n"
        << "comment ergo triangle mesh, unit "
        << (options.unit == LengthUnit::kMillimetre ? "mm" : "m") << "\n"
        << "element vertex " << mesh.vertices.rows() << "\n"
        << "property double x\nproperty double y\nproperty double z\n"
        << "element face " << mesh.triangles.rows() << "\n"
        << "property list uchar int vertex_indices\nend_header\n";
    for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
      for (int k = 0; k < 3; ++k) {
        const double value = mesh.vertices(v, k) / metres_per_unit;
        if (binary) {
          WriteFloat64LE(out, value);
        } else {
          if (k > 0) out << ' ';
          WriteDouble(out, value);
        }
      }
      if (!binary) out << '\n';
    }
    for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
      if (binary) {
        WriteLittleEndian(out, 3, 1);
        for (int k = 0; k < 3; ++k) WriteInt32LE(out, mesh.triangles(f, k));
      } else {
        out << "3 " << mesh.triangles(f, 0) << ' ' << mesh.triangles(f, 1) << ' '
            << mesh.triangles(f, 2) << '\n';
      }
    }
  });
}

}  // namespace ergo
