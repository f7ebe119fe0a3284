// Checks an .mlx script's filter against the filter's declared parameters (params/): every
// parameter, in order, with its name, its .mlx type and its enum items (and, for a sample at the
// defaults, its default), so meshlabserver 2020.09 (which aborts on a missing parameter) and
// pymeshlab read the script as the plugin declares it.
#pragma once

#include <gtest/gtest.h>

#include <QDomDocument>
#include <QFile>
#include <map>
#include <string>
#include <vector>

#include "param.h"

namespace qdml::test {

// The <Param> elements of the filter called `filter` in the .mlx file at path (empty when the
// file has none).
inline std::vector<QDomElement> mlx_params(const std::string& path, const std::string& filter) {
  QFile file(QString::fromStdString(path));
  EXPECT_TRUE(file.open(QIODevice::ReadOnly)) << path;
  QDomDocument doc;
  EXPECT_TRUE(doc.setContent(&file)) << path;
  std::vector<QDomElement> out;
  const QDomNodeList filters = doc.elementsByTagName("filter");
  for (int f = 0; f < filters.size(); ++f) {
    const QDomElement e = filters.at(f).toElement();
    if (e.attribute("name").toStdString() != filter) continue;
    const QDomNodeList params = e.elementsByTagName("Param");
    for (int i = 0; i < params.size(); ++i) out.push_back(params.at(i).toElement());
  }
  return out;
}

inline void expect_mlx_lists(const std::string& path, const std::string& filter,
                             const std::vector<qd::params::ParamInfo>& declared, bool at_defaults) {
  using qd::params::Type;
  const std::vector<QDomElement> params = mlx_params(path, filter);
  ASSERT_EQ(params.size(), declared.size()) << path << ": " << filter;
  const std::map<Type, QString> types = {
      {Type::Real, "RichFloat"},  {Type::Integer, "RichInt"}, {Type::Boolean, "RichBool"},
      {Type::Choice, "RichEnum"}, {Type::Text, "RichString"}, {Type::SaveFile, "RichSaveFile"}};
  for (std::size_t i = 0; i < params.size(); ++i) {
    const QDomElement& p = params[i];
    const qd::params::ParamInfo& d = declared[i];
    SCOPED_TRACE(path + ": " + d.name);
    EXPECT_EQ(p.attribute("name").toStdString(), d.name);
    EXPECT_EQ(p.attribute("type"), types.at(d.type));
    const std::string value = p.attribute("value").toStdString();
    if (d.type == Type::Choice) {
      ASSERT_EQ(p.attribute("enum_cardinality").toInt(), static_cast<int>(d.choices.size()));
      for (std::size_t k = 0; k < d.choices.size(); ++k)
        EXPECT_EQ(p.attribute(QString("enum_val%1").arg(k)).toStdString(), d.choices[k]);
    }
    if (d.type == Type::SaveFile) {
      EXPECT_EQ(p.attribute("ext").toStdString(), d.extension);
      EXPECT_EQ(value, "") << "a sample writes no file";
    }
    if (!at_defaults) continue;
    switch (d.type) {
      case Type::Real:  // the 2020.09 plugin holds floats
        EXPECT_EQ(static_cast<float>(std::stod(value)),
                  static_cast<float>(std::get<double>(d.default_value)));
        break;
      case Type::Integer:
        EXPECT_EQ(std::stod(value), std::get<double>(d.default_value));
        break;
      case Type::Boolean:
        EXPECT_EQ(value == "true", std::get<double>(d.default_value) != 0);
        break;
      case Type::Choice:
        EXPECT_EQ(d.choices.at(std::stoul(value)), std::get<std::string>(d.default_value));
        break;
      case Type::Text:
      case Type::SaveFile:
        EXPECT_EQ(value, std::get<std::string>(d.default_value));
        break;
    }
  }
}

}  // namespace qdml::test
