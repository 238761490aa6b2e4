#include "problems/profile_block.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <glog/logging.h>
#include <Eigen/Geometry>

#include "ergo/mesh/input_error.h"

namespace ergo {
namespace {

void Validate(const ProfileBlock& b) {
  const double height = b.top_y - b.bottom_y, depth = b.front_z - b.back_z;
  if (!(b.width > 0) || !(height > 0) || !(depth > 0)) {
    throw InputError("block support", "", "the block must have positive width, height and depth",
                     "check the block's dimensions");
  }
  if (!(b.front_radius >= 0) || !(b.front_radius < height) || !(b.front_radius < depth)) {
    throw InputError("block support", "front radius",
                     "the front arc radius must be at least 0 and below the block's height and "
                     "depth",
                     "use 0 <= radius < min(height, depth)");
  }
  if (!(b.top_spacing > 0) || !(b.wall_spacing >= b.top_spacing)) {
    throw InputError("block support", "spacing",
                     "the top spacing must be positive and the wall spacing at least as large",
                     "e.g. top 0.01 m, walls 0.04 m");
  }
}

// The side profile in the (z, y) plane: the region under the top curve, mapped from the
// unit square (u along the block from back to front, t from bottom to top).
class Profile {
 public:
  explicit Profile(const ProfileBlock& b) : b_(b) {
    flat_ = (b.front_z - b.back_z) - b.front_radius;
    top_length_ = flat_ + 0.5 * M_PI * b.front_radius;
  }
  double top_length() const { return top_length_; }

  // The top curve at arc-length fraction u: flat, then the quarter arc down to the front.
  Eigen::Vector2d Top(double u) const {
    const double s = u * top_length_;
    if (s <= flat_) return {b_.back_z + s, b_.top_y};
    const double r = b_.front_radius, angle = (s - flat_) / r;
    return {b_.front_z - r + r * std::sin(angle), b_.top_y - r + r * std::cos(angle)};
  }
  Eigen::Vector2d Bottom(double u) const {
    return {b_.back_z + u * (b_.front_z - b_.back_z), b_.bottom_y};
  }
  // Straight segments from the bottom to the top curve: every row is monotone in z and the
  // rows are nested, so the rows' zipped triangles never overlap.
  Eigen::Vector2d At(double u, double t) const { return (1 - t) * Bottom(u) + t * Top(u); }

 private:
  ProfileBlock b_;
  double flat_ = 0, top_length_ = 0;
};

}  // namespace

TriMesh MakeProfileBlock(const ProfileBlock& b) {
  Validate(b);
  const Profile profile(b);
  const int n_top = std::max(1, static_cast<int>(std::ceil(profile.top_length() / b.top_spacing)));
  const int n_bottom =
      std::max(1, static_cast<int>(std::ceil((b.front_z - b.back_z) / b.wall_spacing)));
  const int stations = std::max(1, static_cast<int>(std::ceil(b.width / b.top_spacing)));
  // Rows of the side caps, graded from the top: the first lies one top spacing below it and
  // the gaps grow by 1.5 per row up to the wall spacing, so the rows under the top (and the
  // arc) run nearly parallel to it and the cap's triangles stay well shaped.
  const double height = b.top_y - b.bottom_y;
  std::vector<double> depth_below_top = {0};
  for (double gap = b.top_spacing; depth_below_top.back() + 1.5 * gap < height;
       gap = std::min(1.5 * gap, b.wall_spacing)) {
    depth_below_top.push_back(depth_below_top.back() + gap);
  }
  depth_below_top.push_back(height);
  const int rows = static_cast<int>(depth_below_top.size()) - 1;
  std::vector<double> row_t(rows + 1);  // 0 = bottom, 1 = top
  for (int j = 0; j <= rows; ++j) row_t[j] = 1 - depth_below_top[rows - j] / height;
  // Row j (0 = bottom, rows = top) has count[j] segments: about its length over its gap to
  // the row above, never more than the row above.
  std::vector<int> count(rows + 1);
  count[rows] = n_top;
  for (int j = rows - 1; j >= 0; --j) {
    const double length = (1 - row_t[j]) * (b.front_z - b.back_z) + row_t[j] * profile.top_length();
    const double gap =
        std::clamp((row_t[j + 1] - row_t[j]) * height, b.top_spacing, b.wall_spacing);
    count[j] = std::clamp(static_cast<int>(std::ceil(length / gap)), n_bottom, count[j + 1]);
  }
  count[0] = n_bottom;
  auto profile_point = [&](int j, int i) {
    return profile.At(static_cast<double>(i) / count[j], row_t[j]);
  };

  // The ring: the profile's boundary, clockwise in (z, y) — along the top from back to
  // front, down the front wall, back along the bottom, up the back wall.
  std::vector<std::array<int, 2>> ring;
  for (int i = 0; i <= count[rows]; ++i) ring.push_back({rows, i});
  for (int j = rows - 1; j >= 1; --j) ring.push_back({j, count[j]});
  for (int i = count[0]; i >= 0; --i) ring.push_back({0, i});
  for (int j = 1; j <= rows - 1; ++j) ring.push_back({j, 0});
  const int ring_size = static_cast<int>(ring.size());

  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 3>> faces;
  auto x_of = [&](int k) { return -0.5 * b.width + b.width * k / stations; };
  for (int k = 0; k <= stations; ++k) {
    for (const auto& [j, i] : ring) {
      const Eigen::Vector2d q = profile_point(j, i);
      points.emplace_back(x_of(k), q.y(), q.x());
    }
  }
  // Tube: quads between ring neighbours and stations; (ring step) × (+x) points outward.
  for (int k = 0; k < stations; ++k) {
    for (int r = 0; r < ring_size; ++r) {
      const int a = k * ring_size + r, b2 = k * ring_size + (r + 1) % ring_size;
      const int c = a + ring_size, d = b2 + ring_size;
      faces.push_back({a, b2, c});
      faces.push_back({b2, d, c});
    }
  }
  // Caps: vertices of a row are ring vertices at its ends and on the top and bottom rows,
  // cap-interior vertices otherwise.
  std::vector<std::vector<int>> ring_slot(rows + 1);
  for (int j = 0; j <= rows; ++j) ring_slot[j].assign(count[j] + 1, -1);
  for (int r = 0; r < ring_size; ++r) ring_slot[ring[r][0]][ring[r][1]] = r;
  for (int side = 0; side < 2; ++side) {
    const int station = side == 0 ? 0 : stations;
    const double sign = side == 0 ? -1.0 : 1.0;
    std::vector<std::vector<int>> id(rows + 1);
    for (int j = 0; j <= rows; ++j) {
      id[j].resize(count[j] + 1);
      for (int i = 0; i <= count[j]; ++i) {
        if (ring_slot[j][i] >= 0) {
          id[j][i] = station * ring_size + ring_slot[j][i];
        } else {
          const Eigen::Vector2d q = profile_point(j, i);
          id[j][i] = static_cast<int>(points.size());
          points.emplace_back(x_of(station), q.y(), q.x());
        }
      }
    }
    auto add = [&](int p, int q, int r) {
      const Eigen::Vector3d n = (points[q] - points[p]).cross(points[r] - points[p]);
      if (n.x() * sign > 0) {
        faces.push_back({p, q, r});
      } else {
        faces.push_back({p, r, q});
      }
    };
    // Zip each pair of rows by the parameter u of their points. Ties advance the upper row:
    // at the front the arc ends tangent to the wall, and the last upper point must then join
    // the lower row's second-last point, not only the wall point straight below it (which
    // would make a sliver of three nearly collinear points).
    for (int j = 0; j < rows; ++j) {
      const int lower = count[j], upper = count[j + 1];
      int i = 0, k = 0;
      while (i < lower || k < upper) {
        const bool advance_lower =
            k == upper ||
            (i < lower && static_cast<double>(i + 1) / lower < static_cast<double>(k + 1) / upper);
        if (advance_lower) {
          add(id[j][i], id[j][i + 1], id[j + 1][k]);
          ++i;
        } else {
          add(id[j][i], id[j + 1][k + 1], id[j + 1][k]);
          ++k;
        }
      }
    }
  }
  TriMesh mesh;
  mesh.vertices.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (size_t v = 0; v < points.size(); ++v) mesh.vertices.row(v) = points[v].transpose();
  mesh.triangles.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (size_t f = 0; f < faces.size(); ++f)
    mesh.triangles.row(f) << faces[f][0], faces[f][1], faces[f][2];
  return mesh;
}

bool OnProfileBlockTop(const ProfileBlock& b, const Eigen::Vector3d& p, double tolerance) {
  if (std::abs(p.x()) >= 0.5 * b.width - tolerance) return false;  // side caps
  if (p.z() <= b.back_z + tolerance) return false;                 // back wall
  if (p.y() <= b.bottom_y + tolerance) return false;               // bottom
  if (p.z() >= b.front_z - tolerance && p.y() <= b.top_y - b.front_radius + tolerance)
    return false;  // vertical front wall
  return true;
}

}  // namespace ergo
