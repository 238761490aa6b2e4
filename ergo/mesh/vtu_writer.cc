#include "ergo/mesh/vtu_writer.h"

#include <cstdint>
#include <cstring>
#include <ostream>

#include <glog/logging.h>

#include "ergo/mesh/atomic_file.h"

namespace ergo {

namespace {

constexpr std::uint8_t kVtkTriangle = 5;
constexpr std::uint8_t kVtkTetra = 10;

// The binary encoding stores the host's bytes and declares them LittleEndian.
#if defined(__BYTE_ORDER__) && defined(__ORDER_LITTLE_ENDIAN__)
static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
              "the binary VTU writer needs a little-endian host");
#endif

bool HostIsLittleEndian() {
  const std::uint16_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

std::string EscapeXml(const std::string& text) {
  std::string escaped;
  for (char c : text) {
    switch (c) {
      case '&':
        escaped += "&amp;";
        break;
      case '<':
        escaped += "&lt;";
        break;
      case '>':
        escaped += "&gt;";
        break;
      case '"':
        escaped += "&quot;";
        break;
      default:
        escaped += c;
    }
  }
  return escaped;
}

void WriteText(std::ostream& out, double value) { WriteDouble(out, value); }
void WriteText(std::ostream& out, std::int64_t value) { out << value; }
void WriteText(std::ostream& out, std::uint8_t value) { out << static_cast<int>(value); }

// A matrix's entries row by row (tuple by tuple), converted to T.
template <typename T, typename Matrix>
std::vector<T> RowMajorValues(const Matrix& matrix) {
  std::vector<T> values(static_cast<size_t>(matrix.size()));
  Eigen::Map<Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
      values.data(), matrix.rows(), matrix.cols()) = matrix.template cast<T>();
  return values;
}

// The DataArray elements of one file, in document order. kAscii: the values as text inside
// the element, one tuple per line after `indent`. kBinary: an empty element whose offset
// points into the appended block, which holds each array as its UInt64 byte count and its
// raw values; Finish() writes that block after the XML.
class DataArrays {
 public:
  DataArrays(std::ostream& out, VtuEncoding encoding) : out_(out), encoding_(encoding) {}

  // `values` holds values.size() / components tuples; `name` empty = no Name attribute.
  // ASCII puts `per_line` values on each line (a tuple, or a cell's corners).
  template <typename T>
  void Write(const char* type, const std::string& name, int components,
             const std::vector<T>& values, const char* indent, int per_line) {
    out_ << "        <DataArray type=\"" << type << '"';
    if (!name.empty()) out_ << " Name=\"" << EscapeXml(name) << '"';
    if (components > 1) out_ << " NumberOfComponents=\"" << components << '"';
    if (encoding_ == VtuEncoding::kAscii) {
      out_ << " format=\"ascii\">\n";
      for (size_t i = 0; i < values.size(); i += per_line) {
        out_ << indent;
        for (int k = 0; k < per_line; ++k) {
          if (k > 0) out_ << ' ';
          WriteText(out_, values[i + k]);
        }
        out_ << '\n';
      }
      out_ << "        </DataArray>\n";
      return;
    }
    out_ << " format=\"appended\" offset=\"" << appended_.size() << "\"/>\n";
    const std::uint64_t bytes = values.size() * sizeof(T);
    appended_.append(reinterpret_cast<const char*>(&bytes), sizeof bytes);
    if (bytes > 0) appended_.append(reinterpret_cast<const char*>(values.data()), bytes);
  }

  // Everything after </UnstructuredGrid>. The newline after the raw bytes is what readers
  // (meshio) expect before </AppendedData>.
  void Finish() {
    if (encoding_ == VtuEncoding::kBinary) {
      out_ << "  <AppendedData encoding=\"raw\">\n   _";
      out_.write(appended_.data(), static_cast<std::streamsize>(appended_.size()));
      out_ << "\n  </AppendedData>\n";
    }
    out_ << "</VTKFile>\n";
  }

 private:
  std::ostream& out_;
  const VtuEncoding encoding_;
  std::string appended_;
};

constexpr char kValueIndent[] = "         ";   // Float64 tuples
constexpr char kIndexIndent[] = "          ";  // integer tuples

template <typename Field>
void CheckField(const Field& field, Eigen::Index rows, const char* kind) {
  CHECK(!field.name.empty()) << "VTU " << kind << " field without a name";
  CHECK_EQ(field.values.rows(), rows)
      << "VTU " << kind << " field '" << field.name << "' has the wrong number of rows";
  CHECK(field.values.allFinite()) << "VTU " << kind << " field '" << field.name
                                  << "' holds NaN or infinite values";
}

void WriteData(std::ostream& out, DataArrays* arrays, const char* tag,
               const std::vector<ScalarField>& scalars, const std::vector<VectorField>& vectors) {
  if (scalars.empty() && vectors.empty()) return;
  out << "      <" << tag;
  if (!scalars.empty()) out << " Scalars=\"" << EscapeXml(scalars[0].name) << '"';
  if (!vectors.empty()) out << " Vectors=\"" << EscapeXml(vectors[0].name) << '"';
  out << ">\n";
  for (const ScalarField& field : scalars)
    arrays->Write("Float64", field.name, 1, RowMajorValues<double>(field.values), kValueIndent, 1);
  for (const VectorField& field : vectors)
    arrays->Write("Float64", field.name, 3, RowMajorValues<double>(field.values), kValueIndent, 3);
  out << "      </" << tag << ">\n";
}

template <typename Cells>
void WriteGrid(const std::string& path, const Vertices& vertices, const Cells& cells,
               std::uint8_t vtk_type, const VtuFields& fields, VtuEncoding encoding) {
  CHECK(vertices.allFinite()) << path << ": refusing to write non-finite coordinates";
  if (cells.size() > 0) {
    CHECK_GE(cells.minCoeff(), 0) << path << ": negative vertex index";
    CHECK_LT(cells.maxCoeff(), vertices.rows()) << path << ": vertex index out of range";
  }
  for (const auto& field : fields.point_scalars) CheckField(field, vertices.rows(), "point");
  for (const auto& field : fields.point_vectors) CheckField(field, vertices.rows(), "point");
  for (const auto& field : fields.cell_scalars) CheckField(field, cells.rows(), "cell");
  for (const auto& field : fields.cell_vectors) CheckField(field, cells.rows(), "cell");
  if (encoding == VtuEncoding::kBinary)
    CHECK(HostIsLittleEndian()) << "the binary VTU writer needs a little-endian host";
  const int corners = static_cast<int>(cells.cols());
  std::vector<std::int64_t> offsets(static_cast<size_t>(cells.rows()));
  for (size_t c = 0; c < offsets.size(); ++c)
    offsets[c] = static_cast<std::int64_t>(c + 1) * corners;
  const std::vector<std::uint8_t> types(static_cast<size_t>(cells.rows()), vtk_type);
  WriteFileAtomically(path, [&](std::ostream& out) {
    DataArrays arrays(out, encoding);
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
           "header_type=\"UInt64\">\n"
        << "  <UnstructuredGrid>\n"
        << "    <Piece NumberOfPoints=\"" << vertices.rows() << "\" NumberOfCells=\""
        << cells.rows() << "\">\n";
    WriteData(out, &arrays, "PointData", fields.point_scalars, fields.point_vectors);
    WriteData(out, &arrays, "CellData", fields.cell_scalars, fields.cell_vectors);
    out << "      <Points>\n";
    arrays.Write("Float64", "", 3, RowMajorValues<double>(vertices), kValueIndent, 3);
    out << "      </Points>\n      <Cells>\n";
    // One flat array of vertex ids (one component); ASCII shows a cell per line.
    arrays.Write("Int64", "connectivity", 1, RowMajorValues<std::int64_t>(cells), kIndexIndent,
                 corners);
    arrays.Write("Int64", "offsets", 1, offsets, kIndexIndent, 1);
    arrays.Write("UInt8", "types", 1, types, kIndexIndent, 1);
    out << "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n";
    arrays.Finish();
  });
}

}  // namespace

const char* VtuEncodingName(VtuEncoding encoding) {
  return encoding == VtuEncoding::kBinary ? "binary" : "ascii";
}

bool ParseVtuEncoding(const std::string& text, VtuEncoding* encoding) {
  for (VtuEncoding candidate : {VtuEncoding::kBinary, VtuEncoding::kAscii}) {
    if (text == VtuEncodingName(candidate)) {
      *encoding = candidate;
      return true;
    }
  }
  return false;
}

void WriteVtu(const std::string& path, const TriMesh& mesh, const VtuFields& fields,
              VtuEncoding encoding) {
  WriteGrid(path, mesh.vertices, mesh.triangles, kVtkTriangle, fields, encoding);
}

void WriteVtu(const std::string& path, const TetMesh& mesh, const VtuFields& fields,
              VtuEncoding encoding) {
  WriteGrid(path, mesh.vertices, mesh.tets, kVtkTetra, fields, encoding);
}

}  // namespace ergo
