// The SVG and DXF writers: well-formed output that reads back to the pattern it was given.
#include <gtest/gtest.h>

#include <locale>
#include <sstream>

#include "flatten/dxf_writer.h"
#include "flatten/svg_writer.h"

namespace {

// Two pieces: a 4×2 rectangle with two notches (patch 3), a triangle (patch −1, label "-1.1").
qd::Pattern two_pieces() {
  qd::PatternPiece rect;
  rect.patch = 3;
  rect.label = "3";
  rect.outlines = {{{0, 0}, {4, 0}, {4, 2}, {0, 2}}};
  rect.cut_outlines = rect.outlines;
  rect.notches = {{{4, 1}, {-1, 0}, {4, 1}}, {{2, 0}, {0, 1}, {2, 0}}};
  rect.label_at = {2, 1};
  qd::PatternPiece tri;
  tri.patch = -1;
  tri.label = "-1.1";
  tri.outlines = {{{5, 0}, {7, 0}, {6, 1.5}}};
  tri.cut_outlines = tri.outlines;
  tri.label_at = {6, 0.5};
  return qd::make_pattern({rect, tri});
}

// A small well-formedness check of XML: declarations skipped, every tag closed in order,
// attribute values quoted, no bare '<' or '&' in text. Returns the root element's name.
std::string xml_root(const std::string& xml) {
  std::vector<std::string> open;
  std::string root;
  size_t i = 0;
  while ((i = xml.find('<', i)) != std::string::npos) {
    const size_t end = xml.find('>', i);
    if (end == std::string::npos) throw std::runtime_error("unclosed tag");
    const std::string tag = xml.substr(i + 1, end - i - 1);
    const size_t text_end = xml.find('<', end);
    const std::string text = xml.substr(end + 1, text_end == std::string::npos ? std::string::npos : text_end - end - 1);
    for (size_t a = text.find('&'); a != std::string::npos; a = text.find('&', a + 1))
      if (text.find(';', a) == std::string::npos) throw std::runtime_error("bare & in text");
    i = end + 1;
    if (tag[0] == '?') continue;
    if (std::count(tag.begin(), tag.end(), '"') % 2 != 0) throw std::runtime_error("unbalanced quotes in <" + tag + ">");
    if (tag[0] == '/') {
      if (open.empty() || open.back() != tag.substr(1)) throw std::runtime_error("mismatched </" + tag + ">");
      open.pop_back();
      continue;
    }
    const std::string name = tag.substr(0, tag.find_first_of(" /"));
    if (open.empty()) {
      if (!root.empty()) throw std::runtime_error("two root elements");
      root = name;
    }
    if (tag.back() != '/') open.push_back(name);
  }
  if (!open.empty()) throw std::runtime_error("<" + open.back() + "> not closed");
  return root;
}

TEST(SvgWriter, WellFormedWithOutlinesLabelsNotchesAndAScaleBar) {
  std::ostringstream out;
  out.imbue(std::locale("C"));
  qd::write_svg(out, two_pieces(), "cm");
  const std::string svg = out.str();
  EXPECT_EQ(xml_root(svg), "svg");
  EXPECT_NE(svg.find("version=\"1.1\" width=\""), std::string::npos);  // cm: prints at 1:1
  EXPECT_NE(svg.find("cm\" height=\""), std::string::npos);
  EXPECT_NE(svg.find("id=\"piece-3\""), std::string::npos);
  EXPECT_NE(svg.find("id=\"piece--1.1\""), std::string::npos);
  EXPECT_NE(svg.find(">-1.1</text>"), std::string::npos);
  EXPECT_NE(svg.find(">1 cm</text>"), std::string::npos);  // a quarter of the 7-unit width, down to 1-2-5
  EXPECT_EQ(std::count(svg.begin(), svg.end(), 'Z'), 2);   // two closed outlines
  const size_t notches = svg.find("class=\"notches\"");
  ASSERT_NE(notches, std::string::npos);
  const std::string d = svg.substr(notches, svg.find("/>", notches) - notches);
  EXPECT_EQ(std::count(d.begin(), d.end(), 'M'), 2);
  std::ostringstream plain;
  qd::write_svg(plain, two_pieces());
  EXPECT_EQ(plain.str().find("version=\"1.1\" width=\""), std::string::npos);
  EXPECT_NE(plain.str().find(">1 model units</text>"), std::string::npos);
}

// DXF as (group code, value) pairs.
std::vector<std::pair<int, std::string>> dxf_groups(const std::string& dxf) {
  std::istringstream in(dxf);
  std::vector<std::pair<int, std::string>> groups;
  std::string code, value;
  while (std::getline(in, code)) {
    if (!std::getline(in, value)) throw std::runtime_error("a group code without a value");
    groups.emplace_back(std::stoi(code), value);
  }
  return groups;
}

TEST(DxfWriter, GroupPairsReadBackToThePattern) {
  const qd::Pattern pattern = two_pieces();
  std::ostringstream out;
  qd::write_dxf(out, pattern);
  const auto g = dxf_groups(out.str());
  ASSERT_GE(g.size(), 4u);
  EXPECT_EQ(g.front(), (std::pair<int, std::string>{0, "SECTION"}));
  EXPECT_EQ(g.back(), (std::pair<int, std::string>{0, "EOF"}));
  EXPECT_NE(std::find(g.begin(), g.end(), std::pair<int, std::string>{1, "AC1009"}), g.end());
  // Walk the entities: each POLYLINE is closed (70 = 1), has its outline's vertices, then SEQEND.
  std::vector<std::vector<Eigen::Vector2d>> polylines;
  std::vector<std::string> layers;
  int lines = 0;
  bool closed = false;
  for (size_t i = 0; i < g.size(); ++i) {
    if (g[i].first != 0) continue;
    std::map<int, std::string> fields;
    for (size_t j = i + 1; j < g.size() && g[j].first != 0; ++j) fields[g[j].first] = g[j].second;
    if (g[i].second == "POLYLINE") {
      polylines.emplace_back();
      layers.push_back(fields[8]);
      closed = std::stoi(fields[70]) == 1;
      EXPECT_EQ(std::stoi(fields[66]), 1);
    } else if (g[i].second == "VERTEX") {
      polylines.back().emplace_back(std::stod(fields[10]), std::stod(fields[20]));
      EXPECT_EQ(fields[8], layers.back());
    } else if (g[i].second == "SEQEND") {
      EXPECT_TRUE(closed);
    } else if (g[i].second == "LINE") {
      EXPECT_EQ(fields[8], "PATCH_3_NOTCHES");
      ++lines;
    }
  }
  ASSERT_EQ(polylines.size(), 2u);
  EXPECT_EQ(layers, (std::vector<std::string>{"PATCH_3", "PATCH_-1"}));
  for (size_t p = 0; p < 2; ++p) {
    const auto& outline = pattern.pieces[p].outlines[0];
    ASSERT_EQ(polylines[p].size(), outline.size());
    for (size_t v = 0; v < outline.size(); ++v) EXPECT_LT((polylines[p][v] - outline[v]).norm(), 1e-9);
  }
  EXPECT_EQ(lines, 2);
  // Every layer used is in the LAYER table.
  for (const char* layer : {"PATCH_3", "PATCH_3_NOTCHES", "PATCH_-1", "PATCH_-1_NOTCHES"})
    EXPECT_NE(std::find(g.begin(), g.end(), std::pair<int, std::string>{2, layer}), g.end()) << layer;
}

}  // namespace
