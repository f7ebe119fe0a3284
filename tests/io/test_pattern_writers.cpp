// The SVG, plain DXF and AAMA DXF writers: well-formed output that reads back to the pattern it
// was given, with its cut and sew lines, notches, grainlines and labels.
#include <gtest/gtest.h>

#include <locale>
#include <map>
#include <sstream>

#include "common/error.h"
#include "flatten/outline_measures.h"
#include "io/aama_dxf_writer.h"
#include "io/dxf_writer.h"
#include "io/piece_marks.h"
#include "io/svg_writer.h"

namespace {

using namespace qd::common;
using namespace qd::flatten;

// Two pieces: a 4×2 rectangle with two notches (patch 3), a triangle (patch −1, label "-1.1").
qd::flatten::Pattern two_pieces() {
  qd::flatten::PatternPiece rect;
  rect.patch = 3;
  rect.label = "3";
  rect.outlines = {{{0, 0}, {4, 0}, {4, 2}, {0, 2}}};
  rect.cut_outlines = rect.outlines;
  rect.notches = {{{4, 1}, {-1, 0}, {4, 1}}, {{2, 0}, {0, 1}, {2, 0}}};
  rect.label_at = {2, 1};
  rect.name = "front";
  rect.quantity = 2;
  rect.mirrored = 1;
  qd::flatten::PatternPiece tri;
  tri.patch = -1;
  tri.label = "-1.1";
  tri.outlines = {{{5, 0}, {7, 0}, {6, 1.5}}};
  tri.cut_outlines = tri.outlines;
  tri.label_at = {6, 0.5};
  return qd::flatten::make_pattern({rect, tri});
}

// The same with a seam allowance of 0.5 on the rectangle: its cut line 5×3, notches cut through.
qd::flatten::Pattern with_allowance() {
  qd::flatten::Pattern pattern = two_pieces();
  qd::flatten::PatternPiece& rect = pattern.pieces[0];
  rect.cut_outlines = {{{-0.5, -0.5}, {4.5, -0.5}, {4.5, 2.5}, {-0.5, 2.5}}};
  rect.notches = {{{4, 1}, {-1, 0}, {4.5, 1}}, {{2, 0}, {0, 1}, {2, -0.5}}};
  return pattern;
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
    const std::string text =
        xml.substr(end + 1, text_end == std::string::npos ? std::string::npos : text_end - end - 1);
    for (size_t a = text.find('&'); a != std::string::npos; a = text.find('&', a + 1))
      if (text.find(';', a) == std::string::npos) throw std::runtime_error("bare & in text");
    i = end + 1;
    if (tag[0] == '?') continue;
    if (std::count(tag.begin(), tag.end(), '"') % 2 != 0)
      throw std::runtime_error("unbalanced quotes in <" + tag + ">");
    if (tag[0] == '/') {
      if (open.empty() || open.back() != tag.substr(1))
        throw std::runtime_error("mismatched </" + tag + ">");
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
  qd::io::write_svg(out, two_pieces(), "cm");
  const std::string svg = out.str();
  EXPECT_EQ(xml_root(svg), "svg");
  EXPECT_NE(svg.find("version=\"1.1\" width=\""), std::string::npos);  // cm: prints at 1:1
  EXPECT_NE(svg.find("cm\" height=\""), std::string::npos);
  EXPECT_NE(svg.find("id=\"piece-3\""), std::string::npos);
  EXPECT_NE(svg.find("id=\"piece--1.1\""), std::string::npos);
  EXPECT_NE(svg.find(">Piece -1.1</text>"), std::string::npos);
  EXPECT_NE(svg.find(">front</text>"), std::string::npos);
  EXPECT_NE(svg.find(">Cut 2 (1 mirrored)</text>"), std::string::npos);
  EXPECT_NE(svg.find(">4 \u00d7 2 cm</text>"), std::string::npos);
  EXPECT_EQ(svg.find("class=\"sew\""), std::string::npos);  // no allowance: one line
  EXPECT_NE(svg.find("class=\"grain\""), std::string::npos);
  EXPECT_NE(svg.find(">1 cm</text>"),
            std::string::npos);  // a quarter of the 7-unit width, down to 1-2-5
  EXPECT_EQ(std::count(svg.begin(), svg.end(), 'Z'), 2);  // two closed outlines
  const size_t notches = svg.find("class=\"notches\"");
  ASSERT_NE(notches, std::string::npos);
  const std::string d = svg.substr(notches, svg.find("/>", notches) - notches);
  EXPECT_EQ(std::count(d.begin(), d.end(), 'M'), 2);
  std::ostringstream plain;
  qd::io::write_svg(plain, two_pieces());
  EXPECT_EQ(plain.str().find("version=\"1.1\" width=\""), std::string::npos);
  EXPECT_NE(plain.str().find(">1 model units</text>"), std::string::npos);
  EXPECT_NE(plain.str().find(">4 \u00d7 2 model units</text>"), std::string::npos);
}

TEST(SvgWriter, WithAnAllowanceDrawsTheSewLineDashedInsideTheCutLine) {
  std::ostringstream out;
  qd::io::write_svg(out, with_allowance(), "mm");
  const std::string svg = out.str();
  EXPECT_EQ(xml_root(svg), "svg");
  const size_t sew = svg.find("class=\"sew\" stroke-dasharray=");
  ASSERT_NE(sew, std::string::npos);
  EXPECT_LT(svg.find("class=\"cut\""), sew);
  EXPECT_EQ(std::count(svg.begin(), svg.end(), 'Z'), 3);            // two cut lines, one sew line
  EXPECT_NE(svg.find(">5 \u00d7 3 mm</text>"), std::string::npos);  // the cut line's size
}

TEST(PieceMarks, GrainlineAndNotchTicks) {
  const qd::flatten::PatternPiece rect = with_allowance().pieces[0];
  const qd::io::Segment2 grain =
      qd::io::grainline(rect);  // +y through (2, 1), 60 % of the 3-unit extent
  EXPECT_LT((grain.from - Eigen::Vector2d(2, 0.1)).norm(), 1e-12);
  EXPECT_LT((grain.to - Eigen::Vector2d(2, 1.9)).norm(), 1e-12);
  qd::flatten::PatternPiece sliver = rect;  // a piece 0.4 high: the grainline stays inside it
  sliver.outlines = {{{0, 0.8}, {4, 0.8}, {4, 1.2}, {0, 1.2}}};
  const qd::io::Segment2 clipped = qd::io::grainline(sliver);
  EXPECT_LT((clipped.from - Eigen::Vector2d(2, 0.82)).norm(), 1e-12);
  EXPECT_LT((clipped.to - Eigen::Vector2d(2, 1.18)).norm(), 1e-12);
  const qd::io::Segment2 tick =
      qd::io::notch_tick(rect.notches[0], 0.25);  // from the cut line inward
  EXPECT_LT((tick.from - Eigen::Vector2d(4.5, 1)).norm(), 1e-12);
  EXPECT_LT((tick.to - Eigen::Vector2d(3.75, 1)).norm(), 1e-12);
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
  const qd::flatten::Pattern pattern = two_pieces();
  std::ostringstream out;
  qd::io::write_dxf(out, pattern);
  const auto g = dxf_groups(out.str());
  ASSERT_GE(g.size(), 4u);
  EXPECT_EQ(g.front(), (std::pair<int, std::string>{0, "SECTION"}));
  EXPECT_EQ(g.back(), (std::pair<int, std::string>{0, "EOF"}));
  EXPECT_NE(std::find(g.begin(), g.end(), std::pair<int, std::string>{1, "AC1009"}), g.end());
  // Walk the entities: each POLYLINE is closed (70 = 1), has its outline's vertices, then SEQEND.
  std::vector<std::vector<Eigen::Vector2d>> polylines;
  std::vector<std::string> layers;
  std::map<std::string, int> lines_on;
  std::vector<std::string> texts;
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
      ++lines_on[fields[8]];
    } else if (g[i].second == "TEXT") {
      texts.push_back(fields[1]);
    }
  }
  ASSERT_EQ(polylines.size(), 2u);
  EXPECT_EQ(layers, (std::vector<std::string>{"PATCH_3", "PATCH_-1"}));
  for (size_t p = 0; p < 2; ++p) {
    const auto& outline = pattern.pieces[p].outlines[0];
    ASSERT_EQ(polylines[p].size(), outline.size());
    for (size_t v = 0; v < outline.size(); ++v)
      EXPECT_LT((polylines[p][v] - outline[v]).norm(), 1e-9);
  }
  EXPECT_EQ(lines_on, (std::map<std::string, int>{
                          {"PATCH_3_NOTCHES", 2}, {"PATCH_3_GRAIN", 1}, {"PATCH_-1_GRAIN", 1}}));
  for (const char* text : {"front", "Piece 3", "Cut 2 (1 mirrored)", "Piece -1.1", "Cut 1"})
    EXPECT_NE(std::find(texts.begin(), texts.end(), text), texts.end()) << text;
  // Every layer used is in the LAYER table.
  for (const char* layer : {"PATCH_3", "PATCH_3_NOTCHES", "PATCH_3_GRAIN", "PATCH_3_SEW",
                            "PATCH_-1", "PATCH_-1_NOTCHES", "PATCH_-1_GRAIN"})
    EXPECT_NE(std::find(g.begin(), g.end(), std::pair<int, std::string>{2, layer}), g.end())
        << layer;
}

TEST(DxfWriter, WithAnAllowanceTheSewLineHasItsOwnLayer) {
  std::ostringstream out;
  qd::io::write_dxf(out, with_allowance());
  const auto g = dxf_groups(out.str());
  std::map<std::string, int> polylines_on;
  for (size_t i = 0; i + 2 < g.size(); ++i)
    if (g[i] == std::pair<int, std::string>{0, "POLYLINE"}) ++polylines_on[g[i + 1].second];
  EXPECT_EQ(polylines_on,
            (std::map<std::string, int>{{"PATCH_3", 1}, {"PATCH_3_SEW", 1}, {"PATCH_-1", 1}}));
}

// The AAMA file's sections: per BLOCK its name and the layers of its entities; the INSERTs.
struct AamaFile {
  std::map<std::string, std::vector<std::string>> blocks;  // name -> entity types with layers
  std::map<std::string, std::vector<Eigen::Vector2d>> boundaries;  // name -> layer 1 vertices
  std::vector<std::string> inserts, texts, layers;
  std::string measurement;
};

AamaFile read_aama(const std::string& dxf) {
  const auto g = dxf_groups(dxf);
  AamaFile f;
  std::string block, polyline_layer, previous;
  for (size_t i = 0; i < g.size(); ++i) {
    if (g[i].first == 9 && g[i].second == "$MEASUREMENT") f.measurement = g[i + 1].second;
    if (g[i].first != 0) continue;
    std::map<int, std::string> fields;
    for (size_t j = i + 1; j < g.size() && g[j].first != 0; ++j) fields[g[j].first] = g[j].second;
    const std::string& type = g[i].second;
    if (type == "LAYER") f.layers.push_back(fields[2]);
    if (type == "BLOCK")
      block = fields[2];
    else if (type == "ENDBLK")
      block.clear();
    else if (type == "INSERT")
      f.inserts.push_back(fields[2]);
    else if (type == "TEXT")
      f.texts.push_back(fields[1]);
    if (type == "POLYLINE") polyline_layer = fields[8];
    if (type == "VERTEX" && polyline_layer == "1")
      f.boundaries[block].emplace_back(std::stod(fields[10]), std::stod(fields[20]));
    if (!block.empty() && type != "BLOCK" && type != "VERTEX" && type != "SEQEND")
      f.blocks[block].push_back(type + "@" + fields[8]);
  }
  return f;
}

TEST(AamaDxfWriter, OneBlockPerPieceOnTheStandardLayersWithUnits) {
  const qd::flatten::Pattern pattern = with_allowance();
  std::ostringstream out;
  qd::io::write_aama_dxf(out, pattern, "cm");
  const AamaFile f = read_aama(out.str());
  for (const char* layer : {"1", "4", "7", "11", "14", "15"})
    EXPECT_NE(std::find(f.layers.begin(), f.layers.end(), layer), f.layers.end()) << layer;
  EXPECT_EQ(f.inserts, (std::vector<std::string>{"PIECE_3", "PIECE_-1_1"}));
  ASSERT_EQ(f.blocks.size(), 2u);
  const auto& rect = f.blocks.at("PIECE_3");
  EXPECT_EQ(std::count(rect.begin(), rect.end(), "POLYLINE@1"), 1);
  EXPECT_EQ(std::count(rect.begin(), rect.end(), "POLYLINE@14"), 1);
  EXPECT_EQ(std::count(rect.begin(), rect.end(), "LINE@4"), 2);
  EXPECT_EQ(std::count(rect.begin(), rect.end(), "LINE@7"), 1);
  EXPECT_GE(std::count(rect.begin(), rect.end(), "TEXT@15"), 3);
  const auto& tri = f.blocks.at("PIECE_-1_1");
  EXPECT_EQ(std::count(tri.begin(), tri.end(), "POLYLINE@14"), 0);  // no allowance there
  for (const char* text : {"Units: METRIC", "Piece Name: front", "Quantity: 2",
                           "Piece Name: Piece -1.1", "50 x 30 mm"})
    EXPECT_NE(std::find(f.texts.begin(), f.texts.end(), text), f.texts.end()) << text;
  EXPECT_EQ(f.measurement, "     1");
  // cm are written as mm: the boundary's area is 100 times the cut line's.
  EXPECT_NEAR(qd::flatten::outline_area({f.boundaries.at("PIECE_3")}),
              100 * qd::flatten::outline_area(pattern.pieces[0].cut_outlines), 1e-9);
  EXPECT_NEAR(qd::flatten::outline_length({f.boundaries.at("PIECE_-1_1")}),
              10 * qd::flatten::outline_length(pattern.pieces[1].cut_outlines), 1e-9);
}

TEST(AamaDxfWriter, InchesAreEnglishAndAModelUnitIsRefused) {
  std::ostringstream out;
  qd::io::write_aama_dxf(out, two_pieces(), "in");
  const AamaFile f = read_aama(out.str());
  EXPECT_NE(std::find(f.texts.begin(), f.texts.end(), "Units: ENGLISH"), f.texts.end());
  EXPECT_EQ(f.measurement, "     0");
  std::ostringstream refused;
  EXPECT_THROW(qd::io::write_aama_dxf(refused, two_pieces(), ""), qd::common::Error);
}

}  // namespace
