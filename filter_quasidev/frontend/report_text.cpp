#include "report_text.h"

namespace qd::frontend {

std::string report_text(const Json& report) {
  return report.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace qd::frontend
