#include "ergo/mesh/mesh_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <new>
#include <numeric>
#include <sstream>

#include "ergo/mesh/input_error.h"
#include "ergo/mesh/mesh_check_steps.h"
#include "ergo/mesh/text_reader.h"

namespace ergo {

namespace check {

namespace {

// A mesh spanning more than this is no body part (metres).
constexpr double kLargestBodyPart = 3.0;
// A mesh spanning less than this is too small for a body part or support (metres).
constexpr double kSmallestBodyPart = 0.01;

std::string Metres(long double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3Lg m", value);
  return text;
}

}  // namespace

std::string FormatPoint(const Eigen::Vector3d& p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.6g, %.6g, %.6g)", p.x(), p.y(), p.z());
  return text;
}

namespace {

// " (line 40)", or " (line 40 of body.node)" when the line is in another file than `source`.
std::string LineOf(const std::vector<int>& lines, int64_t index, const std::string& file,
                   const std::string& source) {
  if (index < 0 || index >= static_cast<int64_t>(lines.size())) return "";
  std::string text = " (line " + std::to_string(lines[static_cast<size_t>(index)]);
  if (!file.empty() && file != source) {
    text += " of " + std::filesystem::path(file).filename().string();
  }
  return text + ")";
}

}  // namespace

std::string Context::Vertex(int64_t v) const {
  const std::string name = "vertex " + std::to_string(v);
  return details ? name + LineOf(details->vertex_lines, v, details->vertex_file, source) : name;
}

std::string Context::Element(const char* kind, int64_t e) const {
  const std::string name = std::string(kind) + " " + std::to_string(e);
  return details ? name + LineOf(details->element_lines, e, details->element_file, source) : name;
}

void Tally::Report(const std::string& what, const std::string& fix, MeshCheckReport* report) const {
  if (count_ == 0) return;
  MeshIssue issue;
  issue.severity = severity_;
  issue.code = code_;
  issue.what = what;
  issue.fix = fix;
  issue.count = count_;
  issue.examples = examples_;
  report->issues.push_back(std::move(issue));
}

std::vector<int> CheckCoincidentVertices(const Vertices& vertices, const std::vector<bool>& used,
                                         const Context& context, MeshCheckReport* report) {
  const int n = static_cast<int>(vertices.rows());
  std::vector<int> order(static_cast<size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  auto less = [&](int a, int b) {
    for (int k = 0; k < 3; ++k) {
      if (vertices(a, k) != vertices(b, k)) return vertices(a, k) < vertices(b, k);
    }
    return a < b;
  };
  std::sort(order.begin(), order.end(), less);
  std::vector<int> weld(static_cast<size_t>(n));
  std::iota(weld.begin(), weld.end(), 0);
  Tally tally(Severity::kProblem, "coincident-vertices", context.options.max_examples);
  int first_used = -1;  // first used vertex of the current group of equal positions
  for (int i = 0; i < n; ++i) {
    const int v = order[static_cast<size_t>(i)];
    const bool same =
        i > 0 &&
        (vertices.row(v).array() == vertices.row(order[static_cast<size_t>(i - 1)]).array()).all();
    if (!same) {
      first_used = -1;
    } else {
      weld[static_cast<size_t>(v)] = weld[static_cast<size_t>(order[static_cast<size_t>(i - 1)])];
    }
    if (!used[static_cast<size_t>(v)]) continue;
    if (first_used < 0) {
      first_used = v;
      continue;
    }
    if (tally.WantsExample()) {
      tally.Add(context.Vertex(v) + " is at the same position as " + context.Vertex(first_used) +
                ", " + FormatPoint(vertices.row(v).transpose()));
    } else {
      tally.Count();
    }
  }
  tally.Report(Counted(tally.count(), "vertex is", "vertices are") +
                   " at exactly the same position as another vertex (the surface has cracks "
                   "or seams there)",
               "weld (merge) coincident vertices, e.g. MeshLab's 'Merge Close Vertices' or "
               "trimesh's merge_vertices()",
               report);
  return weld;
}

void CheckVertexUse(const Vertices& vertices, const std::vector<bool>& used, const Context& context,
                    MeshCheckReport* report) {
  Tally unused(Severity::kNote, "unreferenced-vertices", context.options.max_examples);
  WideVector lo = WideVector::Constant(std::numeric_limits<long double>::infinity());
  WideVector hi = -lo;
  for (Eigen::Index v = 0; v < vertices.rows(); ++v) {
    if (!used[static_cast<size_t>(v)]) {
      if (unused.WantsExample()) {
        unused.Add(context.Vertex(v));
      } else {
        unused.Count();
      }
      continue;
    }
    lo = lo.cwiseMin(WidePoint(vertices, v));
    hi = hi.cwiseMax(WidePoint(vertices, v));
  }
  const char* elements = report->is_tet ? "tetrahedron" : "triangle";
  unused.Report(Counted(unused.count(), "vertex is", "vertices are") + " used by no " + elements,
                "none needed; remove them to save memory", report);
  if (!(lo.array() <= hi.array()).all()) return;
  const long double diagonal = (hi - lo).norm();
  report->bounding_box_diagonal = static_cast<double>(diagonal);  // infinite above 1.8e308 m
  const bool in_mm = context.options.unit == LengthUnit::kMillimetre;
  MeshIssue issue;
  issue.severity = Severity::kProblem;
  if (diagonal > kLargestBodyPart) {
    issue.code = "size-too-large";
    issue.what = "the mesh is " + Metres(diagonal) +
                 " across (bounding-box diagonal): larger than any body part: is the file in "
                 "millimetres?";
    issue.fix = in_mm ? "even read as millimetres it is too large; check the file's scale"
                      : "pass --unit=mm (read the file as millimetres)";
    report->issues.push_back(issue);
  } else if (diagonal < kSmallestBodyPart) {
    issue.code = "size-too-small";
    issue.what = "the mesh is " + Metres(diagonal) +
                 " across (bounding-box diagonal): smaller than 1 cm: wrong unit?";
    issue.fix = in_mm ? "if the file is in metres, pass --unit=m"
                      : "check the file's unit; ergo reads metres (--unit=m) or millimetres "
                        "(--unit=mm)";
    report->issues.push_back(issue);
  }
}

}  // namespace check

namespace {

MeshIssue Unusable(const std::string& location, const std::string& what, const std::string& fix) {
  MeshIssue issue;
  issue.severity = Severity::kUnusable;
  issue.code = "unreadable";
  issue.location = location;
  issue.what = what;
  issue.fix = fix;
  return issue;
}

void AddReaderNotes(const ReadDetails* details, MeshCheckReport* report) {
  if (!details) return;
  report->format = details->format;
  for (const ReadNote& note : details->notes) {
    MeshIssue issue;
    issue.severity = note.is_problem ? Severity::kProblem : Severity::kNote;
    issue.code = note.is_problem ? "file-problem" : "file-note";
    issue.location = note.location;
    issue.what = note.what;
    issue.fix = note.fix;
    report->issues.push_back(std::move(issue));
  }
}

// An in-memory mesh with NaN or bad indices cannot be checked further.
template <typename Elements>
bool ValidateIndices(const Vertices& vertices, const Elements& elements, const char* kind,
                     MeshCheckReport* report) {
  if (!vertices.allFinite()) {
    report->issues.push_back(Unusable("", "some vertex coordinates are NaN or infinite",
                                      "repair the mesh: every coordinate must be finite"));
    return false;
  }
  for (Eigen::Index e = 0; e < elements.rows(); ++e) {
    for (Eigen::Index k = 0; k < elements.cols(); ++k) {
      if (elements(e, k) < 0 || elements(e, k) >= vertices.rows()) {
        report->issues.push_back(Unusable(std::string(kind) + " " + std::to_string(e),
                                          "refers to vertex " + std::to_string(elements(e, k)) +
                                              ", but the mesh has " +
                                              std::to_string(vertices.rows()) + " vertices",
                                          "every index must name an existing vertex"));
        return false;
      }
    }
  }
  if (elements.rows() == 0) {
    report->issues.push_back(
        Unusable("", std::string("the mesh has no ") + kind + "s", "pass a mesh with elements"));
    return false;
  }
  return true;
}

template <typename Elements>
std::vector<bool> UsedVertices(Eigen::Index vertex_count, const Elements& elements) {
  std::vector<bool> used(static_cast<size_t>(vertex_count), false);
  for (Eigen::Index e = 0; e < elements.rows(); ++e) {
    for (Eigen::Index k = 0; k < elements.cols(); ++k) used[elements(e, k)] = true;
  }
  return used;
}

}  // namespace

const char* SeverityName(Severity severity) {
  switch (severity) {
    case Severity::kNote:
      return "note";
    case Severity::kProblem:
      return "problem";
    case Severity::kUnusable:
      return "unusable";
  }
  return "?";
}

Severity MeshCheckReport::Worst() const {
  Severity worst = Severity::kNote;
  for (const MeshIssue& issue : issues) worst = std::max(worst, issue.severity);
  return worst;
}

const MeshIssue* MeshCheckReport::Find(const std::string& code) const {
  for (const MeshIssue& issue : issues) {
    if (issue.code == code) return &issue;
  }
  return nullptr;
}

std::string MeshCheckReport::BriefReport() const {
  std::ostringstream out;
  out << file << ": ";
  const Severity worst = Worst();
  if (worst == Severity::kUnusable) {
    for (const MeshIssue& issue : issues) {
      if (issue.severity != Severity::kUnusable) continue;
      std::string where = issue.file;
      if (!issue.location.empty()) where += (where.empty() ? "" : ":") + issue.location;
      out << "unusable: " << (where.empty() ? "" : where + ": ") << issue.what;
      break;
    }
    return out.str();
  }
  int problems = 0, notes = 0;
  std::string codes;
  for (const MeshIssue& issue : issues) {
    if (issue.severity == Severity::kProblem) {
      ++problems;
      codes += (codes.empty() ? "" : ", ") + issue.code;
    } else {
      ++notes;
    }
  }
  if (problems == 0) {
    out << "clean";
  } else {
    out << problems << (problems == 1 ? " kind of problem" : " kinds of problems") << " (" << codes
        << ")";
  }
  if (notes > 0) out << ", " << notes << (notes == 1 ? " note" : " notes");
  return out.str();
}

std::string MeshCheckReport::FullReport() const {
  std::ostringstream out;
  if (Worst() != Severity::kUnusable) {
    out << file << ": " << (format.empty() ? "" : format + ", ")
        << (is_tet ? "tetrahedral mesh, " : "triangle surface, ") << vertices << " vertices, "
        << (is_tet ? tets : triangles) << (is_tet ? " tetrahedra" : " triangles");
    char size[48];
    if (std::isinf(bounding_box_diagonal)) {
      std::snprintf(size, sizeof size, ", more than %.4g m across",
                    std::numeric_limits<double>::max());
    } else {
      std::snprintf(size, sizeof size, ", %.4g m across", bounding_box_diagonal);
    }
    out << size << " (elements and vertices are numbered from 0)\n";
  }
  std::vector<const MeshIssue*> sorted;
  for (const MeshIssue& issue : issues) sorted.push_back(&issue);
  std::stable_sort(sorted.begin(), sorted.end(), [](const MeshIssue* a, const MeshIssue* b) {
    return a->severity > b->severity;
  });
  for (const MeshIssue* issue : sorted) {
    out << (issue->file.empty() ? file : issue->file)
        << (issue->location.empty() ? "" : ":" + issue->location) << ": "
        << SeverityName(issue->severity) << ": " << issue->what << " [" << issue->code << "]\n";
    for (const std::string& example : issue->examples)
      out << "  " << file << ": " << example << '\n';
    if (issue->count > static_cast<int64_t>(issue->examples.size()) && !issue->examples.empty()) {
      out << "  ... and " << issue->count - static_cast<int64_t>(issue->examples.size())
          << " more\n";
    }
    if (!issue->fix.empty()) out << "  fix: " << issue->fix << '\n';
  }
  const int exit_code = ExitCode();
  out << file << ": verdict: "
      << (exit_code == 0   ? "clean"
          : exit_code == 1 ? "problems found"
                           : "unusable")
      << " (exit " << exit_code << ")\n";
  return out.str();
}

MeshCheckReport CheckTriMesh(const TriMesh& mesh, const std::string& source,
                             const MeshCheckOptions& options, const ReadDetails* details) {
  MeshCheckReport report;
  report.file = source;
  report.vertices = mesh.vertices.rows();
  report.triangles = mesh.triangles.rows();
  AddReaderNotes(details, &report);
  if (!ValidateIndices(mesh.vertices, mesh.triangles, "triangle", &report)) return report;
  const check::Context context{source, options, details};
  const std::vector<bool> used = UsedVertices(mesh.vertices.rows(), mesh.triangles);
  const std::vector<int> weld =
      check::CheckCoincidentVertices(mesh.vertices, used, context, &report);
  check::CheckVertexUse(mesh.vertices, used, context, &report);
  check::CheckSurface(mesh, weld, context, &report);
  return report;
}

MeshCheckReport CheckTetMesh(const TetMesh& mesh, const std::string& source,
                             const MeshCheckOptions& options, const ReadDetails* details) {
  MeshCheckReport report;
  report.file = source;
  report.is_tet = true;
  report.vertices = mesh.vertices.rows();
  report.tets = mesh.tets.rows();
  AddReaderNotes(details, &report);
  if (!ValidateIndices(mesh.vertices, mesh.tets, "tetrahedron", &report)) return report;
  const check::Context context{source, options, details};
  const std::vector<bool> used = UsedVertices(mesh.vertices.rows(), mesh.tets);
  check::CheckCoincidentVertices(mesh.vertices, used, context, &report);
  check::CheckVertexUse(mesh.vertices, used, context, &report);
  check::CheckVolume(mesh, context, &report);
  return report;
}

MeshCheckReport CheckMeshFile(const std::string& path, const MeshCheckOptions& options) {
  ReadDetails details;
  AnyMesh mesh;
  try {
    ReadOptions read_options;
    read_options.unit = options.unit;
    mesh = ReadAnyMesh(path, read_options, &details);
  } catch (const InputError& error) {
    MeshCheckReport report;
    report.file = path;
    report.issues.push_back(Unusable(error.location(), error.problem(), error.fix()));
    if (error.source() != path) report.issues.back().file = error.source();
    return report;
  } catch (const std::bad_alloc&) {
    MeshCheckReport report;
    report.file = path;
    report.issues.push_back(
        Unusable("", "ran out of memory while reading the file", "check the file's size"));
    return report;
  }
  return mesh.is_tet ? CheckTetMesh(mesh.volume, path, options, &details)
                     : CheckTriMesh(mesh.surface, path, options, &details);
}

}  // namespace ergo
