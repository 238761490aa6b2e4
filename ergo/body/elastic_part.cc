#include "ergo/body/elastic_part.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <glog/logging.h>
#include <Eigen/LU>

#include "ergo/material/rest_shape_derivative.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/sparse_index.h"
#include "ergo/mesh/tet_components.h"

namespace ergo {
namespace {

// Every connected component of `mesh` must be held by three non-collinear vertices, else its
// stiffness is singular (a free body, or a hinge about the held line).
void RequireEachComponentHeld(const TetMesh& mesh, const std::vector<bool>& held,
                              const std::string& name) {
  const TetComponents components = LabelTetComponents(mesh);
  const double size =
      (mesh.vertices.colwise().maxCoeff() - mesh.vertices.colwise().minCoeff()).norm();
  for (int c = 0; c < components.count; ++c) {
    std::vector<Eigen::Vector3d> points;
    Eigen::Index first = -1, count = 0;
    for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
      if (components.vertex_component[v] != c) continue;
      if (first < 0) first = v;
      ++count;
      if (held[v]) points.push_back(mesh.vertices.row(v).transpose());
    }
    // The held points' spread off the line through the first and the farthest from it.
    double off_line = 0;
    if (points.size() >= 3) {
      size_t far = 0;
      for (size_t i = 1; i < points.size(); ++i)
        if ((points[i] - points[0]).norm() > (points[far] - points[0]).norm()) far = i;
      const Eigen::Vector3d axis = (points[far] - points[0]).normalized();
      for (const Eigen::Vector3d& p : points)
        off_line = std::max(off_line, (p - points[0] - (p - points[0]).dot(axis) * axis).norm());
    }
    if (!(off_line > 1e-9 * size)) {
      throw InputError(name,
                       "connected component " + std::to_string(c) + " (" + std::to_string(count) +
                           " vertices from vertex " + std::to_string(first) + ")",
                       points.empty() ? "has no held vertex: it would float away"
                                      : "is held only along a line or at a point: it would "
                                        "turn about it",
                       "hold its base (the bottom face, or a vertex set spanning an area)");
    }
  }
}

}  // namespace

ElasticPart ElasticPart::Create(TetMesh rest, std::vector<bool> held, TissueMaterial material,
                                const ElasticPartOptions& options, const std::string& name) {
  ValidateTetMaterial(rest, material, name, "foam: 2e4–1.25e5 Pa");
  const Eigen::Index n = rest.vertices.rows();
  if (static_cast<Eigen::Index>(held.size()) != n) {
    throw InputError(name, "",
                     "the held-vertex flags have " + std::to_string(held.size()) + " entries for " +
                         std::to_string(n) + " vertices",
                     "give one flag per tet-mesh vertex");
  }
  if (std::none_of(held.begin(), held.end(), [](bool h) { return h; })) {
    throw InputError(name, "", "no vertex is held: the part would float away",
                     "hold its base (the bottom face, or a vertex set)");
  }
  RequireEachComponentHeld(rest, held, name);
  if (!(options.density >= 0) || !options.gravity.allFinite()) {
    throw InputError(name, "", "density must be >= 0 and gravity finite",
                     "use a foam's density (30–80 kg/m³) or 0");
  }
  ElasticPart part;
  part.rest_ = std::move(rest);
  part.held_ = std::move(held);
  part.material_ = std::move(material);
  part.options_ = options;
  part.free_index_ = Eigen::VectorXi::Constant(n, -1);
  std::vector<int> free;
  for (Eigen::Index v = 0; v < n; ++v) {
    if (part.held_[v]) continue;
    part.free_index_[v] = static_cast<int>(free.size());
    free.push_back(static_cast<int>(v));
  }
  part.free_vertices_ = Eigen::Map<Eigen::VectorXi>(free.data(), free.size());
  part.vertex_mass_ = Eigen::VectorXd::Zero(n);
  for (Eigen::Index t = 0; t < part.rest_.tets.rows(); ++t) {
    const double mass = options.density * TetVolume(part.rest_, t) / 4;
    for (int k = 0; k < 4; ++k) part.vertex_mass_[part.rest_.tets(t, k)] += mass;
  }
  part.boundary_ = ExtractBoundary(part.rest_);
  part.kernel_ = std::make_shared<const TetKernel>(part.rest_, part.material_);
  part.BuildPattern();
  return part;
}

ElasticPart ElasticPart::Join(const std::vector<const ElasticPart*>& parts,
                              const std::string& name) {
  CHECK(!parts.empty());
  const ElasticPart& first = *parts.front();
  Eigen::Index vertices = 0, tets = 0;
  for (const ElasticPart* part : parts) {
    vertices += part->rest_.vertices.rows();
    tets += part->rest_.tets.rows();
  }
  TetMesh mesh;
  mesh.vertices.resize(vertices, 3);
  mesh.tets.resize(tets, 4);
  std::vector<bool> held;
  TissueMaterial material = first.material_;
  material.youngs_modulus.resize(tets);
  material.poisson_ratio.resize(tets);
  bool stiffening = false;
  for (const ElasticPart* part : parts)
    stiffening |= part->material_.stiffening_exponent.size() != 0;
  material.stiffening_exponent.resize(stiffening ? tets : 0);
  Eigen::Index v0 = 0, t0 = 0;
  for (size_t p = 0; p < parts.size(); ++p) {
    const ElasticPart& part = *parts[p];
    if (part.options_.density != first.options_.density ||
        part.options_.gravity != first.options_.gravity ||
        part.material_.compression_resistance != first.material_.compression_resistance ||
        part.material_.inversion_threshold != first.material_.inversion_threshold) {
      throw InputError(name, "soft support " + std::to_string(p + 1),
                       "has another density, gravity or volume-term constant than the first",
                       "give every soft support of a scene the same density");
    }
    const Eigen::Index nv = part.rest_.vertices.rows(), nt = part.rest_.tets.rows();
    mesh.vertices.middleRows(v0, nv) = part.rest_.vertices;
    mesh.tets.middleRows(t0, nt) = part.rest_.tets.array() + static_cast<int>(v0);
    material.youngs_modulus.segment(t0, nt) = part.material_.youngs_modulus;
    material.poisson_ratio.segment(t0, nt) = part.material_.poisson_ratio;
    for (Eigen::Index t = 0; stiffening && t < nt; ++t)
      material.stiffening_exponent[t0 + t] = StiffeningExponentOf(part.material_, t);
    held.insert(held.end(), part.held_.begin(), part.held_.end());
    v0 += nv;
    t0 += nt;
  }
  return Create(std::move(mesh), std::move(held), std::move(material), first.options_, name);
}

ElasticPart ElasticPart::WithRestPositions(const Vertices& rest) const {
  CHECK_EQ(rest.rows(), rest_.vertices.rows());
  ElasticPart part = *this;
  part.rest_.vertices = rest;
  for (Eigen::Index t = 0; t < rest_.tets.rows(); ++t) {
    if (!(TetVolume(part.rest_, t) > 0)) {
      throw InputError("rest shape", "tet " + std::to_string(t),
                       "the designed rest shape inverts or flattens this tet",
                       "take a shorter design step");
    }
  }
  part.vertex_mass_.setZero();
  for (Eigen::Index t = 0; t < rest_.tets.rows(); ++t) {
    const double mass = options_.density * TetVolume(part.rest_, t) / 4;
    for (int k = 0; k < 4; ++k) part.vertex_mass_[rest_.tets(t, k)] += mass;
  }
  for (Eigen::Index i = 0; i < boundary_.surface_to_tet.size(); ++i)
    part.boundary_.surface.vertices.row(i) = rest.row(boundary_.surface_to_tet[i]);
  part.kernel_ = std::make_shared<const TetKernel>(part.rest_, part.material_);
  return part;
}

void ElasticPart::BuildPattern() {
  const Tetrahedra& tets = rest_.tets;
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index t = 0; t < tets.rows(); ++t) {
    for (int a = 0; a < 4; ++a) {
      const int fa = free_index_[tets(t, a)];
      for (int b = 0; b < 4; ++b) {
        const int fb = free_index_[tets(t, b)];
        if (fa < 0 || fb < 0 || fb < fa) continue;
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c)
            if (fa != fb || r <= c) entries.emplace_back(3 * fa + r, 3 * fb + c, 0.0);
      }
    }
  }
  const auto n = static_cast<int>(size());
  pattern_.resize(n, n);
  pattern_.setFromTriplets(entries.begin(), entries.end());
  pattern_.makeCompressed();
  std::fill(pattern_.valuePtr(), pattern_.valuePtr() + pattern_.nonZeros(), 0.0);
  plans_.resize(static_cast<size_t>(tets.rows()));
  for (Eigen::Index t = 0; t < tets.rows(); ++t) {
    for (int a = 0; a < 4; ++a) {
      for (int b = 0; b < 4; ++b) {
        std::array<int, 3>& slot = plans_[t][4 * a + b];
        slot = {-1, -1, -1};
        const int fa = free_index_[tets(t, a)], fb = free_index_[tets(t, b)];
        if (fa < 0 || fb < 0 || fb < fa) continue;
        for (int c = 0; c < 3; ++c) slot[c] = ValueIndex(pattern_, 3 * fa, 3 * fb + c);
      }
    }
  }
}

Vertices ElasticPart::Positions(const Vertices& base,
                                const Eigen::VectorXd& free_displacement) const {
  CHECK_EQ(free_displacement.size(), size());
  Vertices positions = base;
  for (Eigen::Index f = 0; f < free_vertices_.size(); ++f)
    positions.row(free_vertices_[f]) += free_displacement.segment<3>(3 * f).transpose();
  return positions;
}

Eigen::VectorXd ElasticPart::FreeComponents(const Vertices& vertex_field) const {
  Eigen::VectorXd out(size());
  for (Eigen::Index f = 0; f < free_vertices_.size(); ++f)
    out.segment<3>(3 * f) = vertex_field.row(free_vertices_[f]).transpose();
  return out;
}

double ElasticPart::Energy(const Vertices& positions) const {
  double energy = 0;
  for (Eigen::Index t = 0; t < rest_.tets.rows(); ++t)
    energy += kernel_->Energy(t, TetCorners(positions, rest_.tets.row(t)));
  for (Eigen::Index v = 0; v < positions.rows(); ++v)
    energy -= vertex_mass_[v] * options_.gravity.dot(positions.row(v).transpose());
  return energy;
}

void ElasticPart::Evaluate(const Vertices& positions, HessianKind kind, bool with_hessian,
                           Evaluation* evaluation) const {
  Evaluation& e = *evaluation;
  e.with_hessian = with_hessian;
  e.energy = 0;
  e.vertex_gradient = Vertices::Zero(positions.rows(), 3);
  if (with_hessian) {
    if (e.hessian.nonZeros() != pattern_.nonZeros() || e.hessian.rows() != pattern_.rows())
      e.hessian = pattern_;
    std::fill(e.hessian.valuePtr(), e.hessian.valuePtr() + e.hessian.nonZeros(), 0.0);
  }
  double* values = with_hessian ? e.hessian.valuePtr() : nullptr;
  const Tetrahedra& tets = rest_.tets;
  for (Eigen::Index t = 0; t < tets.rows(); ++t) {
    const TetPositions x = TetCorners(positions, tets.row(t));
    Vector12d gradient;
    Matrix12d hessian;
    e.energy += with_hessian ? kernel_->EnergyGradientHessian(t, x, kind, &gradient, &hessian)
                             : kernel_->EnergyGradient(t, x, &gradient);
    for (int k = 0; k < 4; ++k)
      e.vertex_gradient.row(tets(t, k)) += gradient.segment<3>(3 * k).transpose();
    if (!with_hessian) continue;
    for (int a = 0; a < 4; ++a) {
      for (int b = 0; b < 4; ++b) {
        const std::array<int, 3>& slot = plans_[t][4 * a + b];
        if (slot[0] < 0) continue;
        for (int c = 0; c < 3; ++c) {
          const int rows = a == b ? c + 1 : 3;  // a diagonal block: its upper triangle
          for (int r = 0; r < rows; ++r) values[slot[c] + r] += hessian(3 * a + r, 3 * b + c);
        }
      }
    }
  }
  for (Eigen::Index v = 0; v < positions.rows(); ++v) {
    e.energy -= vertex_mass_[v] * options_.gravity.dot(positions.row(v).transpose());
    e.vertex_gradient.row(v) -= vertex_mass_[v] * options_.gravity.transpose();
  }
}

Eigen::VectorXd ElasticPart::VonMisesStress(const Vertices& positions) const {
  Eigen::VectorXd out(rest_.tets.rows());
  for (Eigen::Index t = 0; t < rest_.tets.rows(); ++t) {
    const Eigen::Matrix3d f =
        DeformationGradient(kernel_->rest(t), TetCorners(positions, rest_.tets.row(t)));
    const double j = f.determinant();
    const Eigen::Matrix3d sigma = kernel_->material(t).FirstPiola(f) * f.transpose() / j;
    const Eigen::Matrix3d deviator = sigma - sigma.trace() / 3 * Eigen::Matrix3d::Identity();
    out[t] = std::sqrt(1.5 * deviator.squaredNorm());
  }
  return out;
}

Eigen::VectorXd ElasticPart::VolumeChange(const Vertices& positions) const {
  Eigen::VectorXd out(rest_.tets.rows());
  for (Eigen::Index t = 0; t < rest_.tets.rows(); ++t)
    out[t] = DeformationGradient(kernel_->rest(t), TetCorners(positions, rest_.tets.row(t)))
                 .determinant() -
             1;
  return out;
}

Vertices ElasticPart::RestShapeAdjoint(const Vertices& positions, const Vertices& z) const {
  CHECK_EQ(z.rows(), rest_.vertices.rows());
  Vertices out = Vertices::Zero(rest_.vertices.rows(), 3);
  const Tetrahedra& tets = rest_.tets;
  for (Eigen::Index t = 0; t < tets.rows(); ++t) {
    Vector12d z_element = Vector12d::Zero();
    for (int k = 0; k < 4; ++k)
      if (!held_[tets(t, k)]) z_element.segment<3>(3 * k) = z.row(tets(t, k)).transpose();
    if (z_element.squaredNorm() == 0) continue;
    const TetPositions rest = TetCorners(rest_.vertices, tets.row(t));
    const TetPositions x = TetCorners(positions, tets.row(t));
    Vector12d change =
        ElementForceRestJacobian(kernel_->material(t), rest, x).transpose() * z_element;
    if (options_.density > 0) {
      // The weight −m_i g of each corner holds ρ V/4: its change through dV/dX.
      double z_dot_g = 0;
      for (int k = 0; k < 4; ++k) z_dot_g += z_element.segment<3>(3 * k).dot(options_.gravity);
      change -= options_.density / 4 * z_dot_g * TetVolumeRestGradient(rest);
    }
    for (int k = 0; k < 4; ++k) out.row(tets(t, k)) += change.segment<3>(3 * k).transpose();
  }
  return out;
}

}  // namespace ergo
