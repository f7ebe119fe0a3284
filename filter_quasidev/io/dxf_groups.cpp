#include "io/dxf_groups.h"

#include <iomanip>

namespace qd::io {

DxfGroups::DxfGroups(std::ostream& out)
    : out_(out),
      previous_locale_(out.imbue(std::locale::classic())),
      previous_precision_(out.precision(10)) {}

DxfGroups::~DxfGroups() {
  out_.precision(previous_precision_);
  out_.imbue(previous_locale_);
}

DxfGroups& DxfGroups::operator()(int code, const std::string& value) {
  out_ << std::setw(3) << code << '\n' << value << '\n';
  return *this;
}

DxfGroups& DxfGroups::operator()(int code, double value) {
  out_ << std::setw(3) << code << '\n' << value << '\n';
  return *this;
}

DxfGroups& DxfGroups::operator()(int code, int value) {
  out_ << std::setw(3) << code << '\n' << std::setw(6) << value << '\n';
  return *this;
}

DxfGroups& DxfGroups::point(int code, const Eigen::Vector2d& p) {
  return (*this)(code, p.x())(code + 10, p.y())(code + 20, 0.0);
}

void DxfGroups::header(const Eigen::AlignedBox2d& extents, int measurement) {
  (*this)(0, "SECTION")(2, "HEADER")(9, "$ACADVER")(1, "AC1009");
  (*this)(9, "$EXTMIN").point(10, extents.min())(9, "$EXTMAX").point(10, extents.max());
  if (measurement >= 0) (*this)(9, "$MEASUREMENT")(70, measurement);
  (*this)(0, "ENDSEC");
}

void DxfGroups::tables(const std::vector<DxfLayer>& layers, double dash) {
  DxfGroups& g = *this;
  g(0, "SECTION")(2, "TABLES");
  g(0, "TABLE")(2, "LTYPE")(70, 2);
  g(0, "LTYPE")(2, "CONTINUOUS")(70, 0)(3, "Solid line")(72, 65)(73, 0)(40, 0.0);
  g(0, "LTYPE")(2, "DASHED")(70, 0)(3, "Dashed __ __ __")(72, 65)(73, 2)(40, 2 * dash);
  g(49, dash)(49, -dash);
  g(0, "ENDTAB");
  g(0, "TABLE")(2, "LAYER")(70, static_cast<int>(layers.size()));
  for (const DxfLayer& layer : layers)
    g(0, "LAYER")(2, layer.name)(70, 0)(62, layer.colour)(6,
                                                          layer.dashed ? "DASHED" : "CONTINUOUS");
  g(0, "ENDTAB")(0, "ENDSEC");
}

void DxfGroups::polyline(const std::string& layer, const flatten::Outline& loop) {
  (*this)(0, "POLYLINE")(8, layer)(66, 1).point(10, Eigen::Vector2d::Zero())(70, 1);
  for (const Eigen::Vector2d& p : loop) (*this)(0, "VERTEX")(8, layer).point(10, p);
  (*this)(0, "SEQEND")(8, layer);
}

void DxfGroups::line(const std::string& layer, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  (*this)(0, "LINE")(8, layer).point(10, a).point(11, b);
}

void DxfGroups::text(const std::string& layer, const Eigen::Vector2d& at, double height,
                     const std::string& value) {
  (*this)(0, "TEXT")(8, layer).point(10, at)(40, height)(1, value)(72, 1)(73, 2).point(11, at);
}

void DxfGroups::text_lines(const std::string& layer, const Eigen::Vector2d& at, double height,
                           const std::vector<std::string>& lines) {
  const double step = 1.5 * height;
  const double top = at.y() + step * static_cast<double>(lines.size() - 1) / 2;
  for (std::size_t i = 0; i < lines.size(); ++i)
    text(layer, {at.x(), top - step * static_cast<double>(i)}, height, lines[i]);
}

}  // namespace qd::io
