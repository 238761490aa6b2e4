// ergo_mesh: checks, converts and makes mesh files.
//
//   ergo_mesh check FILE [--closed] [--unit=m|mm]
//       reads FILE (.obj .off .ply .stl .msh .node/.ele) and reports every
//       problem with the file, the element or line, and the fix. Exit status: 0
//       clean (notes allowed), 1 problems found, 2 unusable input.
//   ergo_mesh convert IN OUT [--unit=m|mm] [--out_unit=m|mm] [--binary]
//   [--msh22]
//       reads IN and writes OUT in the format of OUT's extension (exit 2 if IN
//       is unusable).
//   ergo_mesh box OUT --lo=X,Y,Z --hi=X,Y,Z [--cells=NX,NY,NZ] [--out_unit=m|mm]
//       writes the closed, outward box [lo, hi] (metres), each face a grid of
//       cells: a plate or slab to stand a body on (ergo_simulate --support).

#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

#include <gflags/gflags.h>
#include <glog/logging.h>

#include "ergo/mesh/input_error.h"
#include "ergo/mesh/length_unit.h"
#include "ergo/mesh/mesh_check.h"
#include "ergo/mesh/mesh_io.h"
#include "ergo/mesh/primitives.h"
#include "tools/common/flag_checks.h"

DEFINE_bool(closed, false, "check: the surface must be closed (open boundary is a problem)");
DEFINE_string(unit, "m", "unit of the input file's coordinates: m or mm");
DEFINE_string(out_unit, "m", "convert, box: unit of the output file's coordinates: m or mm");
DEFINE_bool(binary, false, "convert, box: write binary PLY / STL");
DEFINE_bool(msh22, false, "convert: write gmsh MSH 2.2 instead of 4.1");
DEFINE_string(lo, "", "box: the smallest corner X,Y,Z in metres");
DEFINE_string(hi, "", "box: the largest corner X,Y,Z in metres");
DEFINE_string(cells, "1,1,1", "box: grid cells along x, y and z on each face");
DEFINE_bool(self_intersections, true, "check: look for self-intersections (CGAL)");
DEFINE_int32(max_examples, 5, "check: examples listed per kind of finding");

namespace {

constexpr int kUsageError = 2;

ergo::LengthUnit UnitFlag(const std::string& name, const std::string& value) {
  ergo::LengthUnit unit;
  if (!ergo::ParseLengthUnit(value, &unit)) {
    throw ergo::InputError("--" + name, "", "unknown unit '" + value + "'",
                           "pass --" + name + "=m or --" + name + "=mm");
  }
  return unit;
}

int Check(const std::string& path) {
  ergo::MeshCheckOptions options;
  options.unit = UnitFlag("unit", FLAGS_unit);
  options.require_closed = FLAGS_closed;
  options.check_self_intersections = FLAGS_self_intersections;
  options.max_examples = FLAGS_max_examples < 0 ? 0 : FLAGS_max_examples;
  const ergo::MeshCheckReport report = ergo::CheckMeshFile(path, options);
  std::cout << report.FullReport() << std::flush;
  return report.ExitCode();
}

int Convert(const std::string& in, const std::string& out) {
  ergo::ReadOptions read;
  read.unit = UnitFlag("unit", FLAGS_unit);
  ergo::WriteOptions write;
  write.unit = UnitFlag("out_unit", FLAGS_out_unit);
  write.encoding = FLAGS_binary ? ergo::Encoding::kBinary : ergo::Encoding::kAscii;
  write.msh_version = FLAGS_msh22 ? ergo::MshVersion::k22 : ergo::MshVersion::k41;
  const ergo::AnyMesh mesh = ergo::ReadAnyMesh(in, read);
  if (mesh.is_tet) {
    ergo::WriteTetMesh(out, mesh.volume, write);
  } else {
    ergo::WriteTriMesh(out, mesh.surface, write);
  }
  std::cout << "wrote " << out << "\n";
  return 0;
}

int Box(const std::string& out) {
  if (FLAGS_lo.empty() || FLAGS_hi.empty())
    throw ergo::InputError("--lo", "", "and --hi are required for box",
                           "e.g. --lo=-0.15,-0.1,-0.25 --hi=0.15,-0.08,0.25");
  const Eigen::Vector3d lo = ergo::ParseThreeNumbers("lo", FLAGS_lo, "-0.15,-0.1,-0.25");
  const Eigen::Vector3d hi = ergo::ParseThreeNumbers("hi", FLAGS_hi, "0.15,-0.08,0.25");
  const Eigen::Vector3d cells = ergo::ParseThreeNumbers("cells", FLAGS_cells, "30,1,50");
  for (int k = 0; k < 3; ++k) {
    if (cells[k] != std::floor(cells[k]) || cells[k] < 1 || cells[k] > 1000) {
      throw ergo::InputError("--cells", "",
                             "'" + FLAGS_cells + "' is not three whole numbers 1..1000",
                             "e.g. --cells=30,1,50");
    }
    if (!(hi[k] > lo[k])) {
      throw ergo::InputError("--hi", "", std::string("is not above --lo along ") + "xyz"[k],
                             "give the smallest corner as --lo and the largest as --hi");
    }
  }
  ergo::WriteOptions write;
  write.unit = UnitFlag("out_unit", FLAGS_out_unit);
  write.encoding = FLAGS_binary ? ergo::Encoding::kBinary : ergo::Encoding::kAscii;
  ergo::WriteTriMesh(out, ergo::MakeBox(lo, hi, cells.cast<int>()), write);
  std::cout << "wrote " << out << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  gflags::SetUsageMessage(
      "ergo_mesh check FILE [--closed] [--unit=m|mm]\n"
      "       ergo_mesh convert IN OUT [--unit=m|mm] "
      "[--out_unit=m|mm] [--binary] [--msh22]\n"
      "       ergo_mesh box OUT --lo=X,Y,Z --hi=X,Y,Z [--cells=NX,NY,NZ] [--out_unit=m|mm]");
  try {
    ergo::CheckCommandLine(argc, argv, /*positional=*/3);  // the verb and its files
  } catch (const ergo::InputError& error) {
    std::cerr << error.what() << "\n";
    return kUsageError;
  }
  gflags::ParseCommandLineFlags(&argc, &argv, true);
  ergo::LogToStderrOnly();
  google::InitGoogleLogging(argv[0]);
  const std::string command = argc > 1 ? argv[1] : "";
  try {
    if (command == "check" && argc == 3) return Check(argv[2]);
    if (command == "convert" && argc == 4) return Convert(argv[2], argv[3]);
    if (command == "box" && argc == 3) return Box(argv[2]);
  } catch (const ergo::InputError& error) {
    std::cerr << error.what() << "\n";
    return kUsageError;
  }
  std::cerr << "usage: " << gflags::ProgramUsage() << "\n";
  return kUsageError;
}
