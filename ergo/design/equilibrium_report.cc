#include "ergo/design/equilibrium_report.h"

#include <cstdio>

#include <glog/logging.h>

#include "ergo/design/centre_of_pressure.h"
#include "ergo/ergonomics/pressure_statistics.h"
#include "ergo/mesh/vtu_writer.h"

namespace ergo {
namespace {

Json Vector3Json(const Eigen::Vector3d& v) {
  Json array = Json::array();
  for (int k = 0; k < 3; ++k) array.push_back(v[k]);
  return array;
}

Json StatisticsJson(const PressureStatistics& s) {
  Json json = Json::object();
  json["contact_vertices"] = s.contact_vertices;
  json["peak_pressure_Pa"] = s.peak;
  json["p95_pressure_Pa"] = s.percentile95;
  json["mean_pressure_Pa"] = s.mean;
  json["contact_area_m2"] = s.contact_area;
  json["total_force_N"] = s.total_force;
  return json;
}

}  // namespace

void WriteDeformedBodyVtu(const std::string& path, const LayeredBody& body, const BodyState& state,
                          const ContactPressures& pressures, VtuEncoding encoding) {
  const Vertices positions = DeformedPositions(body, state);
  const Eigen::Index n = positions.rows();
  Eigen::VectorXd pressure = Eigen::VectorXd::Zero(n), smoothed = Eigen::VectorXd::Zero(n),
                  attached(n);
  const Skin& skin = body.skin();
  for (Eigen::Index i = 0; i < skin.vertices.size(); ++i) {
    pressure[skin.vertices[i]] = pressures.human.pressure[i];
    smoothed[skin.vertices[i]] = pressures.human.smoothed[i];
  }
  for (Eigen::Index v = 0; v < n; ++v) attached[v] = body.attached()[v] ? 1.0 : 0.0;
  Eigen::Matrix<double, Eigen::Dynamic, 3> force =
      Eigen::Matrix<double, Eigen::Dynamic, 3>::Zero(n, 3);
  for (Eigen::Index i = 0; i < skin.vertices.size(); ++i)
    force.row(skin.vertices[i]) = pressures.contacts.skin_force.row(i);
  VtuFields fields;
  fields.point_scalars = {
      {"pressure_Pa", pressure}, {"smoothed_pressure_Pa", smoothed}, {"attached", attached}};
  fields.point_vectors = {{"displacement_m", positions - body.rest().vertices},
                          {"contact_force_N", force}};
  fields.cell_scalars = {{"youngs_modulus_Pa", body.material().youngs_modulus}};
  WriteVtu(path, TetMesh{positions, body.rest().tets}, fields, encoding);
}

void WriteSupportVtu(const std::string& path, const TriMesh& support,
                     const ContactPressures& pressures, const Vertices& initial,
                     VtuEncoding encoding) {
  const Eigen::Index n = support.vertices.rows();
  const Eigen::Matrix<double, Eigen::Dynamic, 3> force = pressures.contacts.support_force;
  VtuFields fields;
  fields.point_scalars = {{"pressure_Pa", pressures.support.pressure},
                          {"smoothed_pressure_Pa", pressures.support.smoothed},
                          {"area_m2", pressures.support_areas}};
  fields.point_vectors = {{"contact_force_N", force}};
  if (initial.rows() == n)
    fields.point_vectors.push_back({"displacement_m", support.vertices - initial});
  WriteVtu(path, support, fields, encoding);
}

Vertices SoftSupportPositions(const ElasticPart& part, const BodyState& state) {
  return part.Positions(part.rest().vertices, state.support_displacement.size() > 0
                                                  ? state.support_displacement
                                                  : Eigen::VectorXd::Zero(part.size()));
}

TriMesh SoftSupportSurface(const ElasticPart& part, const TriMesh& surface,
                           const Vertices& positions) {
  const Eigen::VectorXi& to_part = part.boundary().surface_to_tet;
  CHECK_EQ(to_part.size(), surface.vertices.rows());
  TriMesh moved = surface;
  for (Eigen::Index i = 0; i < moved.vertices.rows(); ++i)
    moved.vertices.row(i) = positions.row(to_part[i]);
  return moved;
}

void WriteSoftSupportVtu(const std::string& path, const ElasticPart& part,
                         const Vertices& positions, VtuEncoding encoding) {
  const Eigen::Index n = positions.rows();
  Eigen::VectorXd held(n);
  for (Eigen::Index v = 0; v < n; ++v) held[v] = part.held()[v] ? 1.0 : 0.0;
  VtuFields fields;
  fields.point_scalars = {{"held", held}};
  fields.point_vectors = {{"displacement_m", positions - part.rest().vertices}};
  fields.cell_scalars = {{"von_mises_stress_Pa", part.VonMisesStress(positions)},
                         {"volume_change", part.VolumeChange(positions)},
                         {"youngs_modulus_Pa", part.material().youngs_modulus}};
  WriteVtu(path, TetMesh{positions, part.rest().tets}, fields, encoding);
}

Json TissueCompressionJson(const TissueCompression& c) {
  Json json = Json::object();
  json["min_volume_ratio"] = c.min_volume_ratio;
  json["min_principal_stretch"] = c.min_principal_stretch;
  json["inversion_threshold"] = c.threshold;
  json["tets_beyond_inversion_threshold"] = c.tets_beyond_threshold;
  json["inverted_tets"] = c.inverted_tets;
  json["worst_point_m"] = Vector3Json(c.worst_point);
  return json;
}

std::string DescribeTissueCompression(const TissueCompression& c) {
  if (c.tets_beyond_threshold == 0) return "";
  char line[512];
  std::snprintf(line, sizeof line,
                "warning: the tissue is crushed beyond its material law in %d tet(s) (%d "
                "inverted): a principal stretch down to %.3g, below the inversion threshold %.2g "
                "(more than %.0f %% compression), worst at (%.4g, %.4g, %.4g) m. There the "
                "energy is the law's numerical extension, not tissue: pressures carried through "
                "those tets are not measurements of anything (a stiffer or deeper layer there, "
                "or a support that spreads the load)",
                c.tets_beyond_threshold, c.inverted_tets, c.min_principal_stretch, c.threshold,
                100 * (1 - c.threshold), c.worst_point.x(), c.worst_point.y(), c.worst_point.z());
  return line;
}

Json PlatePeakJson(const PlatePeak& peak, const PlatePeakOptions& options) {
  Json json = Json::object();
  json["pressure_Pa"] = peak.pressure;
  json["pitch_m"] = options.pitch;
  json["cell_centre_xz_m"] = Json::array({peak.point.x(), peak.point.y()});
  return json;
}

Json EquilibriumSummary(const LayeredBody& body, const EquilibriumResult& result,
                        const ContactPressures& pressures, double contact_stiffness,
                        const TissueCompression& compression) {
  const PressureStatistics human =
      ComputePressureStatistics(pressures.human.pressure, body.skin().rest_areas);
  const PressureStatistics support =
      ComputePressureStatistics(pressures.support.pressure, pressures.support_areas);
  Json json = Json::object();
  json["converged"] = result.converged;
  json["status"] = EquilibriumStatusName(result.status);
  json["reason"] = result.message;
  json["iterations"] = result.iterations;
  json["projected_steps"] = result.projected_steps;
  json["residual_N"] = result.residual;
  json["relative_residual"] = result.relative_residual;
  json["contact_vertices"] = result.contact_vertices;
  json["contact_springs"] = result.contact_springs;
  json["factorizations"] = result.factorizations;
  json["symbolic_analyses"] = result.analyses;
  json["analysis_seconds"] = result.analysis_seconds;
  json["max_penetration_m"] = result.max_penetration;
  json["total_contact_force_N"] = Vector3Json(result.contact_force);
  json["load_N"] = Vector3Json(body.TotalLoad());
  json["peak_pressure_Pa"] = human.peak;
  json["p95_pressure_Pa"] = human.percentile95;
  json["mean_pressure_Pa"] = human.mean;
  json["contact_area_m2"] = human.contact_area;
  json["contact_stiffness_Pa_per_m"] = contact_stiffness;
  const CentreOfPressure cop = ComputeCentreOfPressure(body, result.state, pressures.contacts);
  if (cop.normal_force > 0) {
    json["centre_of_pressure_m"] = Vector3Json(cop.point);
    json["centre_of_pressure_z_fraction"] = cop.z_fraction;
  }
  if (LoadSeenAlongY(body.TotalLoad())) {
    json["plate_peak"] = PlatePeakJson(ComputePlatePeak(
        SkinMapFromBelow(body, DeformedPositions(body, result.state), pressures.human.pressure)));
  }
  json["tissue_compression"] = TissueCompressionJson(compression);
  json["energy_J"] = result.energy;
  json["zeta_human"] = pressures.human.cost;
  json["zeta_support"] = pressures.support.cost;
  json["human_side"] = StatisticsJson(human);
  json["support_side"] = StatisticsJson(support);
  Json seconds = Json::object();
  seconds["assembly"] = result.assembly_seconds;
  seconds["contact"] = result.contact_seconds;
  seconds["factorization"] = result.factorization_seconds;
  seconds["solve"] = result.solve_seconds;
  seconds["line_search"] = result.line_search_seconds;
  seconds["total"] = result.total_seconds;
  json["seconds"] = seconds;
  return json;
}

}  // namespace ergo
