#include "ergo/contact/feature.h"

namespace ergo {

const char* FeatureTypeName(FeatureType type) {
  switch (type) {
    case FeatureType::kVertex:
      return "vertex";
    case FeatureType::kEdge:
      return "edge";
    case FeatureType::kFace:
      return "face";
  }
  return "?";
}

std::ostream& operator<<(std::ostream& out, const Feature& feature) {
  out << FeatureTypeName(feature.type) << "(";
  for (int i = 0; i < feature.size(); ++i) out << (i ? "," : "") << feature.vertices[i];
  return out << ")";
}

}  // namespace ergo
