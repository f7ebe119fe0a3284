#include "flatten_settings.h"

#include <charconv>
#include <cmath>

#include "param.h"

namespace qd::params {

std::string direction_text(const Eigen::Vector3d& d) {
  if (d.isZero()) return kLongestAxis;
  return number_text(d.x()) + "," + number_text(d.y()) + "," + number_text(d.z());
}

Eigen::Vector3d parse_direction(const std::string& text) {
  if (text == kLongestAxis) return Eigen::Vector3d::Zero();
  Eigen::Vector3d d;
  const char* at = text.data();
  const char* end = text.data() + text.size();
  for (int i = 0; i < 3; ++i) {
    while (at < end && *at == ' ') ++at;
    const auto [ptr, ec] = std::from_chars(at, end, d[i]);
    at = ptr;
    while (at < end && *at == ' ') ++at;
    if (ec != std::errc() || !std::isfinite(d[i]) ||
        (i < 2 ? at == end || *at++ != ',' : at != end))
      throw ParamError("expects a direction X,Y,Z (three numbers, e.g. 0,1,0) or longest, got '" +
                       text + "'");
  }
  if (d.norm() == 0) throw ParamError("must not be 0,0,0");
  return d;
}

}  // namespace qd::params
