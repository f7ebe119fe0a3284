#include "paper.h"

#include "common/error.h"

namespace qd::pdf {

PageSpec page_spec(params::Paper paper) {
  PageSpec page;
  if (paper == params::Paper::Letter) {
    page.width = 8.5 * 72;
    page.height = 11 * 72;
  } else {
    page.width = 210 * kPointsPerMm;
    page.height = 297 * kPointsPerMm;
  }
  return page;
}

double points_per_unit(params::PatternUnit unit) {
  switch (unit) {
    case params::PatternUnit::Millimetre:
      return kPointsPerMm;
    case params::PatternUnit::Centimetre:
      return 10 * kPointsPerMm;
    case params::PatternUnit::Inch:
      return 72;
    case params::PatternUnit::Model:
      break;
  }
  throw common::Error("a printable PDF needs the model's length unit: pass --unit mm, cm or in");
}

}  // namespace qd::pdf
