// Writing a DXF file of AutoCAD Release 12 (AC1009) group by group (Autodesk, "AutoCAD Release
// 12 DXF Reference"): the group-code/value pairs, the HEADER and TABLES sections (a solid and a
// dashed line type, the layers) and the entities both pattern writers draw (closed POLYLINE,
// LINE, centred TEXT). Writes with the classic locale; restores the stream's on destruction.
#pragma once

#include <locale>
#include <ostream>
#include <string>
#include <vector>

#include "flatten/pattern.h"

namespace qd::io {

struct DxfLayer {
  std::string name;
  int colour = 7;       // AutoCAD colour index
  bool dashed = false;  // line type DASHED, else CONTINUOUS
};

class DxfGroups {
 public:
  explicit DxfGroups(std::ostream& out);
  ~DxfGroups();
  DxfGroups(const DxfGroups&) = delete;
  DxfGroups& operator=(const DxfGroups&) = delete;

  DxfGroups& operator()(int code, const std::string& value);
  DxfGroups& operator()(int code, double value);
  DxfGroups& operator()(int code, int value);
  DxfGroups& point(int code, const Eigen::Vector2d& p);  // code, code + 10, code + 20 (z = 0)

  // HEADER: the version, the drawing's extents and, when measurement is 0 (English) or 1
  // (metric), $MEASUREMENT.
  void header(const Eigen::AlignedBox2d& extents, int measurement = -1);
  // TABLES: LTYPE (CONTINUOUS, and DASHED of dash length `dash`) and LAYER.
  void tables(const std::vector<DxfLayer>& layers, double dash);

  void polyline(const std::string& layer, const flatten::Outline& loop);  // closed
  void line(const std::string& layer, const Eigen::Vector2d& a, const Eigen::Vector2d& b);
  void text(const std::string& layer, const Eigen::Vector2d& at, double height,
            const std::string& value);  // centred on `at`
  // Lines of text stacked and centred on `at`, the first on top.
  void text_lines(const std::string& layer, const Eigen::Vector2d& at, double height,
                  const std::vector<std::string>& lines);

 private:
  std::ostream& out_;
  std::locale previous_locale_;
  std::streamsize previous_precision_;
};

}  // namespace qd::io
