#include "segment/patch_color.h"

#include <cmath>

namespace qd::segment {

std::array<unsigned char, 3> patch_color(int id) {
  constexpr double kGoldenAngle = 0.381966011250105;  // (3 − √5)/2 of a turn
  constexpr double kSaturation = 0.6, kValue = 0.95;
  const double hue = std::fmod(0.1 + kGoldenAngle * id, 1.0) * 6.0;  // sector 0..6
  const int sector = static_cast<int>(hue) % 6;
  const double f = hue - std::floor(hue);
  const double p = kValue * (1 - kSaturation), q = kValue * (1 - kSaturation * f),
               t = kValue * (1 - kSaturation * (1 - f));
  const double rgb[6][3] = {{kValue, t, p}, {q, kValue, p}, {p, kValue, t},
                            {p, q, kValue}, {t, p, kValue}, {kValue, p, q}};
  std::array<unsigned char, 3> c{};
  for (int k = 0; k < 3; ++k) c[k] = static_cast<unsigned char>(std::lround(255 * rgb[sector][k]));
  return c;
}

}  // namespace qd::segment
