#include "ergo/body/anatomical_priors.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>

#include "ergo/mesh/input_error.h"
#include "ergo/mesh/surface_geometry.h"

namespace ergo {
namespace {

// The prior's value at one skin point.
struct TissuePrior {
  double depth = 0, youngs_modulus = 0;  // m, Pa
  double stiffening_exponent = 2;        // α (2: neo-Hookean)
};

double Clamp01(double t) { return std::min(1.0, std::max(0.0, t)); }

// 0 below a, 1 above b, C¹ in between (a < b).
double SmoothStep(double a, double b, double t) {
  const double u = Clamp01((t - a) / (b - a));
  return u * u * (3 - 2 * u);
}

double Mix(double a, double b, double weight) { return a + weight * (b - a); }

TissuePrior Mix(const TissuePrior& a, const TissuePrior& b, double weight) {
  return {Mix(a.depth, b.depth, weight), Mix(a.youngs_modulus, b.youngs_modulus, weight),
          Mix(a.stiffening_exponent, b.stiffening_exponent, weight)};
}

// The part's length axis (z) and its start: `start_at_min` says whether the part starts
// (heel, back, wrist) at the smallest z.
struct LengthFrame {
  double min_z = 0, max_z = 0, floor_y = 0;
  bool start_at_min = true;
  double length() const { return max_z - min_z; }
  double start_z() const { return start_at_min ? min_z : max_z; }
  double direction() const { return start_at_min ? 1.0 : -1.0; }
  // 0 at the start, 1 at the far end.
  double Along(const Eigen::Vector3d& p) const {
    return start_at_min ? (p.z() - min_z) / length() : (max_z - p.z()) / length();
  }
};

LengthFrame FrameOf(const Vertices& v, bool start_at_min) {
  LengthFrame f;
  f.min_z = v.col(2).minCoeff();
  f.max_z = v.col(2).maxCoeff();
  f.floor_y = v.col(1).minCoeff();
  f.start_at_min = start_at_min;
  return f;
}

// Breadth (x extent) and its centre in bins along the part, from the vertices no higher
// than `max_height` above the floor (the part's footprint).
struct BreadthProfile {
  std::vector<double> centre, breadth;  // per bin
  double Bin(double s) const {
    return std::min(centre.size() - 1.0, std::max(0.0, std::floor(s * centre.size())));
  }
  double CentreAt(double s) const { return centre[static_cast<size_t>(Bin(s))]; }
  double BreadthAt(double s) const { return breadth[static_cast<size_t>(Bin(s))]; }
};

BreadthProfile ProfileOf(const Vertices& v, const LengthFrame& frame, double max_height, int bins) {
  std::vector<double> lo(bins, std::numeric_limits<double>::infinity());
  std::vector<double> hi(bins, -std::numeric_limits<double>::infinity());
  for (Eigen::Index i = 0; i < v.rows(); ++i) {
    if (v(i, 1) - frame.floor_y > max_height) continue;
    const double s = frame.Along(v.row(i).transpose());
    const int bin = std::min(bins - 1, std::max(0, static_cast<int>(std::floor(s * bins))));
    lo[bin] = std::min(lo[bin], v(i, 0));
    hi[bin] = std::max(hi[bin], v(i, 0));
  }
  BreadthProfile profile;
  profile.centre.resize(bins);
  profile.breadth.resize(bins);
  const double x_mid = 0.5 * (v.col(0).minCoeff() + v.col(0).maxCoeff());
  for (int b = 0; b < bins; ++b) {
    const bool seen = std::isfinite(lo[b]);
    profile.centre[b] = seen ? 0.5 * (lo[b] + hi[b]) : x_mid;
    profile.breadth[b] = seen ? hi[b] - lo[b] : 0;
  }
  return profile;
}

double Median(std::vector<double> values) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  const size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + mid, values.end());
  return values[mid];
}

// --- Foot -----------------------------------------------------------------------------------

// Plantar soft tissue and the bones' height above the floor (ergo/body/README.md
// "Anatomical priors" gives each value's source).
constexpr double kHeelPadDepth = 0.0175;       // heel pad 16–19 mm
constexpr double kBallPadDepth = 0.015;        // metatarsal-head pad about 15 mm
constexpr double kLateralMidfootBone = 0.015;  // lateral column's underside above the floor
constexpr double kMedialArchBone = 0.035;      // medial arch's bones above the floor
constexpr double kDorsalFootDepth = 0.006;     // over the top and sides of the foot
constexpr double kToeCrease = 0.06;  // the core's cut: this fraction of the length past the ball
constexpr double kHeelModulus = 45e3, kBallModulus = 58e3, kToeModulus = 40e3,
                 kDorsalFootModulus = 40e3;  // Pa
// Between the heel's and the balls' chambered fat pads the plantar tissue is mostly muscle
// (abductor digiti minimi, flexor digitorum brevis, abductor hallucis) and loose fat, like
// the paper's seated tissue (5–15 kPa, §3.1): its upper end.
constexpr double kMidfootModulus = 15e3;  // Pa
// The heel pad's chambered fat stiffens steeply with strain: an Ogden fit to in-vivo
// indentation gives alpha = 6.82 (Erdemir et al. 2006, J Biomech 39:1279) with a small-strain
// shear modulus near Sun et al.'s; the ball's pad, built the same way, takes the same alpha.
// Neo-Hookean (alpha = 2) elsewhere: no plantar fit behind a value there.
constexpr double kFatPadExponent = 6.82;

struct FootModel {
  LengthFrame frame;
  BreadthProfile profile;
  double medial_sign = 1;  // +1: the medial side is +x
  double ball_s = 0.7;     // fraction of the length from the heel
  // The weight-bearing line: through the heel's and the ball's lowest skin points (a scan
  // need not stand level, and its lowest point may be a toe); heights are measured from it.
  double heel_s = 0.1, heel_y = 0, ball_low_s = 0.7, ball_y = 0;

  double FloorAt(double s) const {
    return heel_y + (s - heel_s) / (ball_low_s - heel_s) * (ball_y - heel_y);
  }

  TissuePrior At(const Eigen::Vector3d& p, const Eigen::Vector3d& normal) const {
    const double s = frame.Along(p);
    const double height = p.y() - FloorAt(s);
    // −1 lateral border … +1 medial border of the footprint at s.
    const double half = std::max(1e-3, 0.5 * profile.BreadthAt(s));
    const double across =
        std::max(-1.0, std::min(1.0, medial_sign * (p.x() - profile.CentreAt(s)) / half));
    const double medial = SmoothStep(-0.2, 0.8, across);
    // Height of the bones' underside above the floor along the foot: heel pad, the midfoot
    // (low laterally, the arch medially), the metatarsal heads' pad.
    const double midfoot_bone = Mix(kLateralMidfootBone, kMedialArchBone, medial);
    double bone = Mix(kHeelPadDepth, midfoot_bone, SmoothStep(0.2, 0.32, s));
    bone = Mix(bone, kBallPadDepth, SmoothStep(ball_s - 0.12, ball_s - 0.05, s));
    const double plantar_depth = std::max(bone - height, kDorsalFootDepth);
    const double to_midfoot = SmoothStep(0.2, 0.32, s),
                 to_ball = SmoothStep(ball_s - 0.12, ball_s - 0.05, s);
    const double plantar_modulus =
        Mix(Mix(kHeelModulus, kMidfootModulus, to_midfoot), kBallModulus, to_ball);
    const double plantar_exponent =
        Mix(Mix(kFatPadExponent, 2.0, to_midfoot), kFatPadExponent, to_ball);
    const TissuePrior plantar{plantar_depth, plantar_modulus, plantar_exponent};
    const TissuePrior dorsal{kDorsalFootDepth, kDorsalFootModulus, 2.0};
    // Downward-facing skin is plantar; the sides and the top are dorsal.
    TissuePrior foot = Mix(dorsal, plantar, SmoothStep(0.1, 0.6, -normal.y()));
    const double to_toes = SmoothStep(ball_s + 0.03, ball_s + kToeCrease, s);
    foot.youngs_modulus = Mix(foot.youngs_modulus, kToeModulus, to_toes);
    foot.stiffening_exponent = Mix(foot.stiffening_exponent, 2.0, to_toes);
    return foot;
  }

  // Positive beyond the toe crease, m (the toes have no core).
  double CoreLimit(const Eigen::Vector3d& p) const {
    return (frame.Along(p) - (ball_s + kToeCrease)) * frame.length();
  }
};

FootModel DetectFoot(const Vertices& v, const Vertices& normals, const AnatomyOptions& options,
                     const std::string& source, std::vector<Landmark>* landmarks) {
  const double floor_y = v.col(1).minCoeff();
  const bool heel_at_min = HeelAtMinZ(v, options.heel_end, source);
  FootModel foot;
  foot.frame = FrameOf(v, heel_at_min);
  // The footprint: skin within 4 cm of the floor (below the ankle's bulk).
  foot.profile = ProfileOf(v, foot.frame, 0.04, 50);
  double widest = -1;
  for (int b = 0; b < 50; ++b) {
    const double s = (b + 0.5) / 50;
    if (s < 0.55 || s > 0.85) continue;
    if (foot.profile.breadth[b] > widest) {
      widest = foot.profile.breadth[b];
      foot.ball_s = s;
    }
  }
  // Medial side: where the midfoot's plantar skin is higher (the arch), unless given.
  std::vector<double> plus, minus;
  for (Eigen::Index i = 0; i < v.rows(); ++i) {
    const double s = foot.frame.Along(v.row(i).transpose());
    if (s < 0.35 || s > 0.6 || normals(i, 1) > -0.3) continue;
    (v(i, 0) > foot.profile.CentreAt(s) ? plus : minus).push_back(v(i, 1) - floor_y);
  }
  const double rise = Median(plus) - Median(minus);
  if (options.foot_side != FootSide::kAuto) {
    // y up and the toes along +z: x points to the person's left, so a right foot's medial
    // side (towards the other foot) is +x when the toes point along +z.
    const double right = options.foot_side == FootSide::kRight ? 1.0 : -1.0;
    foot.medial_sign = right * foot.frame.direction();
  } else {
    if (!(std::abs(rise) >= 0.002)) {
      throw InputError(source, "",
                       "cannot tell the medial side: the midfoot's underside is "
                       "as high on both sides (a flat arch, or too few plantar vertices)",
                       "give --foot_side=left or --foot_side=right");
    }
    foot.medial_sign = rise > 0 ? 1 : -1;
  }
  // Landmarks on the skin.
  auto lowest_near = [&](double s0, double s1, double across_lo, double across_hi) {
    Eigen::Index best = -1;
    for (Eigen::Index i = 0; i < v.rows(); ++i) {
      const double s = foot.frame.Along(v.row(i).transpose());
      if (s < s0 || s > s1) continue;
      const double half = std::max(1e-3, 0.5 * foot.profile.BreadthAt(s));
      const double across = foot.medial_sign * (v(i, 0) - foot.profile.CentreAt(s)) / half;
      if (across < across_lo || across > across_hi || normals(i, 1) > -0.3) continue;
      if (best < 0 || v(i, 1) < v(best, 1)) best = i;
    }
    return best;
  };
  Eigen::Index toe = 0;
  for (Eigen::Index i = 0; i < v.rows(); ++i)
    if (foot.frame.Along(v.row(i).transpose()) > foot.frame.Along(v.row(toe).transpose())) toe = i;
  const Eigen::Index heel = lowest_near(0.0, 0.2, -1, 1);
  const Eigen::Index ball = lowest_near(foot.ball_s - 0.04, foot.ball_s + 0.04, -0.5, 0.5);
  // The arch: the medial midfoot's underside (its lowest point is its plantar skin).
  const Eigen::Index arch = lowest_near(0.38, 0.52, 0.3, 0.8);
  if (heel >= 0 && ball >= 0) {
    foot.heel_s = foot.frame.Along(v.row(heel).transpose());
    foot.heel_y = v(heel, 1);
    foot.ball_low_s = foot.frame.Along(v.row(ball).transpose());
    foot.ball_y = v(ball, 1);
  }
  const std::pair<const char*, Eigen::Index> named[] = {
      {"heel", heel}, {"ball", ball}, {"medial arch", arch}, {"toe tip", toe}};
  for (const auto& [name, index] : named) {
    if (index < 0) {
      throw InputError(source, "", std::string("no skin found for the foot's ") + name,
                       "check the scan's axes (--axes): y up, the length along z");
    }
    Landmark mark;
    mark.name = name;
    mark.point = v.row(index).transpose();
    const TissuePrior prior = foot.At(mark.point, normals.row(index).transpose());
    mark.depth = prior.depth;
    mark.youngs_modulus = prior.youngs_modulus;
    mark.stiffening_exponent = prior.stiffening_exponent;
    landmarks->push_back(mark);
  }
  return foot;
}

// --- Seat -----------------------------------------------------------------------------------

constexpr double kIschialDepth = 0.03, kButtockDepth = 0.045, kThighDepth = 0.03,
                 kBackDepth = 0.022;  // m
constexpr double kIschialModulus = 6e3, kButtockModulus = 6e3, kThighModulus = 9e3,
                 kBackModulus = 13e3;    // Pa (paper: 5–15 kPa)
constexpr double kIschialRadius = 0.05;  // m, the region around each tuberosity

struct SeatModel {
  LengthFrame frame;
  Eigen::Vector3d ischial[2];

  TissuePrior At(const Eigen::Vector3d& p, const Eigen::Vector3d& normal) const {
    const double s = frame.Along(p);
    const TissuePrior buttock{kButtockDepth, kButtockModulus};
    const TissuePrior thigh{kThighDepth, kThighModulus};
    const TissuePrior back{kBackDepth, kBackModulus};
    TissuePrior under = Mix(buttock, thigh, SmoothStep(0.45, 0.6, s));
    double near = 0;
    for (const Eigen::Vector3d& tuberosity : ischial) {
      const double horizontal = std::hypot(p.x() - tuberosity.x(), p.z() - tuberosity.z());
      near = std::max(near, 1 - SmoothStep(0.6 * kIschialRadius, kIschialRadius, horizontal));
    }
    under = Mix(under, TissuePrior{kIschialDepth, kIschialModulus}, near);
    // Downward-facing skin is what sits; the back and the top take the lower back's values.
    return Mix(back, under, SmoothStep(-0.2, 0.3, -normal.y()));
  }
};

SeatModel DetectSeat(const Vertices& v, const Vertices& normals, const std::string& source,
                     std::vector<Landmark>* landmarks) {
  SeatModel seat;
  seat.frame = FrameOf(v, true);
  const double x_mid = 0.5 * (v.col(0).minCoeff() + v.col(0).maxCoeff());
  // The ischial tuberosities: the lowest downward-facing skin of each side's rear half.
  Eigen::Index lowest[2] = {-1, -1};
  for (Eigen::Index i = 0; i < v.rows(); ++i) {
    if (seat.frame.Along(v.row(i).transpose()) > 0.5 || normals(i, 1) > -0.5) continue;
    const int side = v(i, 0) > x_mid ? 1 : 0;
    if (lowest[side] < 0 || v(i, 1) < v(lowest[side], 1)) lowest[side] = i;
  }
  const char* names[2] = {"ischial tuberosity (-x)", "ischial tuberosity (+x)"};
  for (int side = 0; side < 2; ++side) {
    if (lowest[side] < 0) {
      throw InputError(source, "", "no downward-facing skin in the rear half on one side",
                       "check the scan's axes (--axes): y up, +z towards the knees");
    }
    seat.ischial[side] = v.row(lowest[side]).transpose();
  }
  for (int side = 0; side < 2; ++side) {
    Landmark mark;
    mark.name = names[side];
    mark.point = seat.ischial[side];
    const TissuePrior prior = seat.At(mark.point, normals.row(lowest[side]).transpose());
    mark.depth = prior.depth;
    mark.youngs_modulus = prior.youngs_modulus;
    mark.stiffening_exponent = prior.stiffening_exponent;
    landmarks->push_back(mark);
  }
  return seat;
}

// --- Hand -----------------------------------------------------------------------------------

constexpr double kPalmDepth = 0.010, kDorsalHandDepth = 0.005, kFingerDepth = 0.004;   // m
constexpr double kPalmModulus = 8e3, kDorsalHandModulus = 8e3, kFingerModulus = 12e3;  // Pa
constexpr double kPalmFraction = 0.56;  // palm length / hand length (wrist to middle fingertip)

struct HandModel {
  LengthFrame frame;

  TissuePrior At(const Eigen::Vector3d& p, const Eigen::Vector3d& normal) const {
    const double s = frame.Along(p);
    const TissuePrior palm =
        Mix(TissuePrior{kDorsalHandDepth, kDorsalHandModulus},
            TissuePrior{kPalmDepth, kPalmModulus}, SmoothStep(-0.2, 0.3, -normal.y()));
    return Mix(palm, TissuePrior{kFingerDepth, kFingerModulus},
               SmoothStep(kPalmFraction - 0.04, kPalmFraction + 0.02, s));
  }
};

HandModel DetectHand(const Vertices& v, const Vertices& normals, const std::string& source,
                     std::vector<Landmark>* landmarks) {
  HandModel hand;
  // The wrist end is the broader one (the fingers taper and separate).
  const LengthFrame trial = FrameOf(v, true);
  const BreadthProfile profile = ProfileOf(v, trial, std::numeric_limits<double>::infinity(), 10);
  const double near_min = profile.breadth[1], near_max = profile.breadth[8];
  if (!(near_min > 0) || !(near_max > 0)) {
    throw InputError(source, "", "the hand's ends could not be measured",
                     "check the scan's axes (--axes): y up, the fingers along z");
  }
  hand.frame = FrameOf(v, near_min >= near_max);
  Eigen::Index palm = -1, tip = 0;
  for (Eigen::Index i = 0; i < v.rows(); ++i) {
    const double s = hand.frame.Along(v.row(i).transpose());
    if (s > hand.frame.Along(v.row(tip).transpose())) tip = i;
    if (std::abs(s - 0.5 * kPalmFraction) < 0.1 && normals(i, 1) < -0.5 &&
        (palm < 0 || v(i, 1) < v(palm, 1)))
      palm = i;
  }
  if (palm < 0) {
    throw InputError(source, "", "no downward-facing skin in the palm's region",
                     "check the scan's axes (--axes): y up with the palm down, fingers along z");
  }
  for (const auto& [name, index] :
       {std::pair<const char*, Eigen::Index>{"palm centre", palm}, {"fingertip", tip}}) {
    Landmark mark;
    mark.name = name;
    mark.point = v.row(index).transpose();
    const TissuePrior prior = hand.At(mark.point, normals.row(index).transpose());
    mark.depth = prior.depth;
    mark.youngs_modulus = prior.youngs_modulus;
    mark.stiffening_exponent = prior.stiffening_exponent;
    landmarks->push_back(mark);
  }
  return hand;
}

// Farthest-point subset of the vertices: spreads the samples evenly over the skin.
std::vector<Eigen::Index> FarthestPoints(const Vertices& v, int count) {
  const Eigen::Index n = v.rows();
  std::vector<Eigen::Index> chosen;
  if (n == 0) return chosen;
  Eigen::VectorXd distance = Eigen::VectorXd::Constant(n, std::numeric_limits<double>::infinity());
  Eigen::Index next = 0;
  for (int k = 0; k < std::min<Eigen::Index>(count, n); ++k) {
    chosen.push_back(next);
    for (Eigen::Index i = 0; i < n; ++i)
      distance[i] = std::min(distance[i], (v.row(i) - v.row(next)).squaredNorm());
    distance.maxCoeff(&next);
  }
  return chosen;
}

}  // namespace

bool HeelAtMinZ(const Vertices& v, HeelEnd heel_end, const std::string& source) {
  if (heel_end != HeelEnd::kAuto) return heel_end == HeelEnd::kMinZ;
  // The heel end carries the ankle: its quarter of the foot reaches higher.
  const double min_z = v.col(2).minCoeff(), max_z = v.col(2).maxCoeff();
  const double length = max_z - min_z, floor_y = v.col(1).minCoeff();
  double top_min = floor_y, top_max = floor_y;
  for (Eigen::Index i = 0; i < v.rows(); ++i) {
    if (v(i, 2) < min_z + 0.25 * length) top_min = std::max(top_min, v(i, 1));
    if (v(i, 2) > max_z - 0.25 * length) top_max = std::max(top_max, v(i, 1));
  }
  const double height = v.col(1).maxCoeff() - floor_y;
  if (std::abs(top_min - top_max) < 0.1 * height) {
    throw InputError(source, "",
                     "cannot tell the heel end: both ends of the foot reach about the same "
                     "height (no ankle)",
                     "give --heel_end=min_z or --heel_end=max_z");
  }
  return top_min > top_max;
}

Anatomy ParseAnatomy(const std::string& text, const std::string& flag) {
  if (text.empty() || text == "none") return Anatomy::kNone;
  if (text == "foot") return Anatomy::kFoot;
  if (text == "seat") return Anatomy::kSeat;
  if (text == "hand") return Anatomy::kHand;
  throw InputError(flag, "", "'" + text + "' is not an anatomy", "use foot, seat, hand or none");
}

HeelEnd ParseHeelEnd(const std::string& text, const std::string& flag) {
  if (text == "auto") return HeelEnd::kAuto;
  if (text == "min_z") return HeelEnd::kMinZ;
  if (text == "max_z") return HeelEnd::kMaxZ;
  throw InputError(flag, "", "'" + text + "' is not a heel end", "use auto, min_z or max_z");
}

FootSide ParseFootSide(const std::string& text, const std::string& flag) {
  if (text == "auto") return FootSide::kAuto;
  if (text == "left") return FootSide::kLeft;
  if (text == "right") return FootSide::kRight;
  throw InputError(flag, "", "'" + text + "' is not a foot side", "use auto, left or right");
}

const char* AnatomyName(Anatomy anatomy) {
  switch (anatomy) {
    case Anatomy::kNone:
      return "none";
    case Anatomy::kFoot:
      return "foot";
    case Anatomy::kSeat:
      return "seat";
    case Anatomy::kHand:
      return "hand";
  }
  return "none";
}

AnatomicalPriors ComputeAnatomicalPriors(const TriMesh& skin, const AnatomyOptions& options,
                                         const std::string& source) {
  if (options.anatomy == Anatomy::kNone)
    throw InputError(source, "", "no anatomy given", "use foot, seat or hand");
  if (skin.vertices.rows() < 4 || skin.triangles.rows() < 4)
    throw InputError(source, "", "the skin has too few vertices for anatomical priors", "");
  const Vertices& v = skin.vertices;
  const Vertices normals = VertexNormals(skin);
  AnatomicalPriors priors;
  std::function<TissuePrior(const Eigen::Vector3d&, const Eigen::Vector3d&)> prior;
  LengthFrame frame;
  std::ostringstream summary;
  if (options.anatomy == Anatomy::kFoot) {
    const FootModel foot = DetectFoot(v, normals, options, source, &priors.landmarks);
    prior = [foot](const Eigen::Vector3d& p, const Eigen::Vector3d& n) { return foot.At(p, n); };
    priors.core_limit = [foot](const Eigen::Vector3d& p) { return foot.CoreLimit(p); };
    frame = foot.frame;
    summary << "foot, heel at " << (frame.start_at_min ? "min" : "max") << " z, medial side "
            << (foot.medial_sign > 0 ? "+x" : "-x") << ", ball at " << std::round(100 * foot.ball_s)
            << " % of the length, the core cut at " << std::round(100 * (foot.ball_s + kToeCrease))
            << " % (the toes are tissue)";
    priors.toe_clearance = std::numeric_limits<double>::infinity();
    for (Eigen::Index i = 0; i < v.rows(); ++i) {
      const Eigen::Vector3d p = v.row(i).transpose();
      if (foot.CoreLimit(p) > 0)
        priors.toe_clearance =
            std::min(priors.toe_clearance, p.y() - foot.FloorAt(foot.frame.Along(p)));
    }
    if (!std::isfinite(priors.toe_clearance)) priors.toe_clearance = 0;
    summary << ", the toes' lowest skin " << std::round(10e3 * priors.toe_clearance) / 10
            << " mm above the line the heel and the ball stand on"
            << (priors.toe_clearance > 0.005
                    ? " (toes held up: a standing foot's rest on the floor)"
                    : "");
    try {
      priors.heel = ScannedHeel{MeasureHeelBisector(skin, frame.start_at_min, foot.medial_sign,
                                                    HeelBisectorOptions(), source)
                                    .eversion,
                                foot.medial_sign};
      const double degrees = priors.heel->eversion * 180 / M_PI;
      summary << ", the heel's bisector " << std::round(10 * std::abs(degrees)) / 10 << " deg "
              << (degrees >= 0 ? "everted" : "inverted") << " as scanned";
    } catch (const InputError&) {
      summary << ", the heel's bisector not drawn (too little of the heel's outline)";
    }
  } else if (options.anatomy == Anatomy::kSeat) {
    const SeatModel seat = DetectSeat(v, normals, source, &priors.landmarks);
    prior = [seat](const Eigen::Vector3d& p, const Eigen::Vector3d& n) { return seat.At(p, n); };
    frame = seat.frame;
    summary << "seat, back at min z";
  } else {
    const HandModel hand = DetectHand(v, normals, source, &priors.landmarks);
    prior = [hand](const Eigen::Vector3d& p, const Eigen::Vector3d& n) { return hand.At(p, n); };
    frame = hand.frame;
    summary << "hand, wrist at " << (frame.start_at_min ? "min" : "max") << " z";
  }
  const double floor = options.min_depth;
  auto floored = [&](TissuePrior value) {
    value.depth = std::max(value.depth, floor);
    return value;
  };
  bool raised = false;
  for (Landmark& mark : priors.landmarks) {
    raised = raised || mark.depth < floor;
    mark.depth = std::max(mark.depth, floor);
  }
  priors.length = frame.length();
  priors.start_z = frame.start_z();
  priors.length_direction = frame.direction();
  summary << ", length " << frame.length() << " m";
  for (const Landmark& mark : priors.landmarks) {
    summary << "; " << mark.name << " depth " << 1e3 * mark.depth << " mm, E "
            << 1e-3 * mark.youngs_modulus << " kPa";
    if (mark.stiffening_exponent != 2.0)
      summary << " (stiffening, alpha " << mark.stiffening_exponent << ")";
  }
  // Farthest-point samples, plus the landmarks themselves (where the priors are defined).
  std::vector<Eigen::Index> chosen = FarthestPoints(v, options.samples);
  for (const Landmark& mark : priors.landmarks) {
    Eigen::Index index = 0;
    (v.rowwise() - mark.point.transpose()).rowwise().squaredNorm().minCoeff(&index);
    if (std::find(chosen.begin(), chosen.end(), index) == chosen.end()) chosen.push_back(index);
  }
  const Eigen::Index count = static_cast<Eigen::Index>(chosen.size());
  for (PointSamples* samples :
       {&priors.depth, &priors.youngs_modulus, &priors.stiffening_exponent}) {
    samples->points.resize(count, 3);
    samples->values.resize(count);
    samples->source = std::string(AnatomyName(options.anatomy)) + " priors";
  }
  for (Eigen::Index k = 0; k < count; ++k) {
    const Eigen::Index i = chosen[k];
    const TissuePrior raw = prior(v.row(i).transpose(), normals.row(i).transpose());
    raised = raised || raw.depth < floor;
    const TissuePrior value = floored(raw);
    priors.depth.points.row(k) = v.row(i);
    priors.depth.values[k] = value.depth;
    priors.youngs_modulus.points.row(k) = v.row(i);
    priors.youngs_modulus.values[k] = value.youngs_modulus;
    priors.stiffening_exponent.points.row(k) = v.row(i);
    priors.stiffening_exponent.values[k] = value.stiffening_exponent;
  }
  if (raised) summary << "; depths below " << 1e3 * floor << " mm raised to it (one edge length)";
  priors.summary = summary.str();
  return priors;
}

PointSamples OverridePriorSamples(const PointSamples& prior, const PointSamples& measured,
                                  double radius) {
  std::vector<Eigen::Index> kept;
  for (Eigen::Index i = 0; i < prior.points.rows(); ++i) {
    bool covered = false;
    for (Eigen::Index j = 0; j < measured.points.rows() && !covered; ++j)
      covered = (prior.points.row(i) - measured.points.row(j)).norm() < radius;
    if (!covered) kept.push_back(i);
  }
  PointSamples merged;
  merged.source = measured.source.empty() ? prior.source : measured.source;
  const Eigen::Index n = static_cast<Eigen::Index>(kept.size()) + measured.points.rows();
  merged.points.resize(n, 3);
  merged.values.resize(n);
  Eigen::Index k = 0;
  for (Eigen::Index i : kept) {
    merged.points.row(k) = prior.points.row(i);
    merged.values[k] = prior.values[i];
    merged.lines.push_back(0);
    ++k;
  }
  for (Eigen::Index j = 0; j < measured.points.rows(); ++j, ++k) {
    merged.points.row(k) = measured.points.row(j);
    merged.values[k] = measured.values[j];
    merged.lines.push_back(j < static_cast<Eigen::Index>(measured.lines.size()) ? measured.lines[j]
                                                                                : 0);
  }
  if (measured.lines.empty()) merged.lines.clear();  // no file lines to name
  return merged;
}

}  // namespace ergo
