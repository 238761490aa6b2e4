#include "ergo/mesh/vtu_writer.h"

#include <ostream>

#include <glog/logging.h>

#include "ergo/mesh/atomic_file.h"

namespace ergo {

namespace {

constexpr int kVtkTriangle = 5;
constexpr int kVtkTetra = 10;

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

template <typename Matrix>
void WriteValues(std::ostream& out, const Matrix& values) {
  for (Eigen::Index i = 0; i < values.rows(); ++i) {
    out << "         ";
    for (Eigen::Index k = 0; k < values.cols(); ++k) {
      if (k > 0) out << ' ';
      WriteDouble(out, values(i, k));
    }
    out << '\n';
  }
}

template <typename Field>
void CheckField(const Field& field, Eigen::Index rows, const char* kind) {
  CHECK(!field.name.empty()) << "VTU " << kind << " field without a name";
  CHECK_EQ(field.values.rows(), rows)
      << "VTU " << kind << " field '" << field.name << "' has the wrong number of rows";
  CHECK(field.values.allFinite()) << "VTU " << kind << " field '" << field.name
                                  << "' holds NaN or infinite values";
}

void WriteData(std::ostream& out, const char* tag, const std::vector<ScalarField>& scalars,
               const std::vector<VectorField>& vectors) {
  if (scalars.empty() && vectors.empty()) return;
  out << "      <" << tag;
  if (!scalars.empty()) out << " Scalars=\"" << EscapeXml(scalars[0].name) << '"';
  if (!vectors.empty()) out << " Vectors=\"" << EscapeXml(vectors[0].name) << '"';
  out << ">\n";
  for (const ScalarField& field : scalars) {
    out << "        <DataArray type=\"Float64\" Name=\"" << EscapeXml(field.name)
        << "\" format=\"ascii\">\n";
    WriteValues(out, field.values);
    out << "        </DataArray>\n";
  }
  for (const VectorField& field : vectors) {
    out << "        <DataArray type=\"Float64\" Name=\"" << EscapeXml(field.name)
        << "\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    WriteValues(out, field.values);
    out << "        </DataArray>\n";
  }
  out << "      </" << tag << ">\n";
}

template <typename Cells>
void WriteGrid(const std::string& path, const Vertices& vertices, const Cells& cells, int vtk_type,
               const VtuFields& fields) {
  CHECK(vertices.allFinite()) << path << ": refusing to write non-finite coordinates";
  if (cells.size() > 0) {
    CHECK_GE(cells.minCoeff(), 0) << path << ": negative vertex index";
    CHECK_LT(cells.maxCoeff(), vertices.rows()) << path << ": vertex index out of range";
  }
  for (const auto& field : fields.point_scalars) CheckField(field, vertices.rows(), "point");
  for (const auto& field : fields.point_vectors) CheckField(field, vertices.rows(), "point");
  for (const auto& field : fields.cell_scalars) CheckField(field, cells.rows(), "cell");
  for (const auto& field : fields.cell_vectors) CheckField(field, cells.rows(), "cell");
  const int corners = static_cast<int>(cells.cols());
  WriteFileAtomically(path, [&](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
           "header_type=\"UInt64\">\n"
        << "  <UnstructuredGrid>\n"
        << "    <Piece NumberOfPoints=\"" << vertices.rows() << "\" NumberOfCells=\""
        << cells.rows() << "\">\n";
    WriteData(out, "PointData", fields.point_scalars, fields.point_vectors);
    WriteData(out, "CellData", fields.cell_scalars, fields.cell_vectors);
    out << "      <Points>\n"
        << "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    WriteValues(out, vertices);
    out << "        </DataArray>\n      </Points>\n      <Cells>\n"
        << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (Eigen::Index c = 0; c < cells.rows(); ++c) {
      out << "         ";
      for (int k = 0; k < corners; ++k) out << ' ' << cells(c, k);
      out << '\n';
    }
    out << "        </DataArray>\n"
        << "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (Eigen::Index c = 0; c < cells.rows(); ++c) {
      out << "          " << (c + 1) * corners << '\n';
    }
    out << "        </DataArray>\n"
        << "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (Eigen::Index c = 0; c < cells.rows(); ++c) out << "          " << vtk_type << '\n';
    out << "        </DataArray>\n      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n"
        << "</VTKFile>\n";
  });
}

}  // namespace

void WriteVtu(const std::string& path, const TriMesh& mesh, const VtuFields& fields) {
  WriteGrid(path, mesh.vertices, mesh.triangles, kVtkTriangle, fields);
}

void WriteVtu(const std::string& path, const TetMesh& mesh, const VtuFields& fields) {
  WriteGrid(path, mesh.vertices, mesh.tets, kVtkTetra, fields);
}

}  // namespace ergo
