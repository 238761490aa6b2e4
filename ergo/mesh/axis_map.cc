#include "ergo/mesh/axis_map.h"

#include <Eigen/LU>

#include "ergo/mesh/input_error.h"
#include "ergo/mesh/split_list.h"

namespace ergo {

Eigen::Matrix3d ParseAxisMap(const std::string& text, const std::string& flag) {
  const std::string fix =
      "give three signed input axes for ergo's x, y (up) and z, e.g. y,z,x (a rotation)";
  const std::vector<std::string> parts = SplitList(text, ',');
  if (parts.size() != 3) throw InputError(flag, "", "'" + text + "' does not name three axes", fix);
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Zero();
  for (int row = 0; row < 3; ++row) {
    std::string axis = parts[row];
    double sign = 1;
    if (!axis.empty() && (axis[0] == '-' || axis[0] == '+')) {
      sign = axis[0] == '-' ? -1 : 1;
      axis = axis.substr(1);
    }
    if (axis != "x" && axis != "y" && axis != "z")
      throw InputError(flag, "", "'" + parts[row] + "' is not an axis (x, y, z, -x, ...)", fix);
    const int column = axis[0] - 'x';
    if (rotation.col(column).squaredNorm() > 0)
      throw InputError(flag, "", "the input axis " + axis + " is used twice in '" + text + "'",
                       fix);
    rotation(row, column) = sign;
  }
  if (rotation.determinant() < 0) {
    throw InputError(flag, "",
                     "'" + text +
                         "' is a mirror, not a rotation (it would turn the "
                         "surface inside out and a left part into a right one)",
                     "flip the sign of one axis, e.g. -" + parts[0]);
  }
  return rotation;
}

void ApplyAxisMap(const Eigen::Matrix3d& rotation, Vertices* points) {
  *points = (*points * rotation.transpose()).eval();
}

}  // namespace ergo
