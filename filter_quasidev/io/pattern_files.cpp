#include "io/pattern_files.h"

#include <sstream>

#include "io/aama_dxf_writer.h"
#include "io/dxf_writer.h"
#include "io/svg_writer.h"

namespace qd::io {

std::vector<std::pair<std::string, std::string>> pattern_files(const params::FlattenSettings& s,
                                                               const flatten::Pattern& pattern) {
  std::vector<std::pair<std::string, std::string>> files;
  const std::string unit = params::svg_unit(s);
  if (!s.svg_file.empty()) {
    std::ostringstream svg;
    write_svg(svg, pattern, unit);
    files.emplace_back(s.svg_file, svg.str());
  }
  if (!s.dxf_file.empty()) {
    std::ostringstream dxf;
    if (s.dxf_style == params::DxfStyle::Aama)
      write_aama_dxf(dxf, pattern, unit);
    else
      write_dxf(dxf, pattern, unit);
    files.emplace_back(s.dxf_file, dxf.str());
  }
  return files;
}

}  // namespace qd::io
