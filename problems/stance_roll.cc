#include "problems/stance_roll.h"

#include <cmath>
#include <sstream>

#include "ergo/mesh/input_error.h"

namespace ergo {

std::string StanceRoll::BriefReport() const {
  std::ostringstream out;
  out.precision(3);
  out << "stance roll " << roll / kDegree << " deg: the heel's bisector " << heel_eversion / kDegree
      << " deg everted at rest (on " << measured_on << "), stood at " << calcaneal_stance / kDegree
      << " deg everted (medial side " << (medial_sign > 0 ? "+x" : "-x") << ")";
  return out.str();
}

StanceRoll StanceRollFrom(const ScannedHeel& heel, double calcaneal_stance, double max_roll,
                          const std::string& measured_on, const std::string& source) {
  const double heel_eversion = heel.eversion, medial_sign = heel.medial_sign;
  if (!std::isfinite(calcaneal_stance))
    throw InputError(source, "calcaneal stance", "not a finite angle", "give degrees, e.g. 6.07");
  if (!std::isfinite(heel_eversion) || !(medial_sign == 1 || medial_sign == -1)) {
    throw InputError(source, "heel",
                     "the heel's bisector or the foot's medial side is unknown, so is the "
                     "stance roll",
                     "give the roll in degrees instead");
  }
  StanceRoll stance;
  stance.heel_eversion = heel_eversion;
  stance.calcaneal_stance = calcaneal_stance;
  stance.medial_sign = medial_sign;
  stance.measured_on = measured_on;
  // A turn by r about +z raises +x: the heel everts by r when the medial side is −x.
  stance.roll = medial_sign * (heel_eversion - calcaneal_stance);
  if (!(std::abs(stance.roll) <= max_roll)) {
    std::ostringstream what;
    what << "the stance roll would be " << stance.roll / StanceRoll::kDegree
         << " degrees (the heel " << heel_eversion / StanceRoll::kDegree
         << " degrees everted at rest), beyond " << max_roll / StanceRoll::kDegree;
    throw InputError(source, "stance roll", what.str(),
                     "check the scan's axes and --foot_side, or give the roll in degrees");
  }
  return stance;
}

StanceRoll FindStanceRoll(const LayeredBody& body, const AnatomyOptions& anatomy,
                          double calcaneal_stance, double max_roll, const std::string& source) {
  AnatomyOptions foot = anatomy;
  foot.anatomy = Anatomy::kFoot;
  const AnatomicalPriors priors =
      ComputeAnatomicalPriors(body.skin().RestSurface(body.rest().vertices), foot, source);
  if (!priors.heel) {
    throw InputError(source, "heel",
                     "the heel's outline could not be bisected, so the stance roll is unknown",
                     "give the roll in degrees instead");
  }
  return StanceRollFrom(*priors.heel, calcaneal_stance, max_roll, "the body's skin", source);
}

}  // namespace ergo
