// Checks a sample .mlx script against a filter's parameter table: every parameter, in order,
// with its name, its .mlx type, its default and its enum items, so meshlabserver 2020.09 (which
// aborts on a missing parameter) and pymeshlab read the script as the plugin declares it.
#pragma once

#include <gtest/gtest.h>

#include <QDomDocument>
#include <QFile>
#include <map>
#include <vector>

#include "filter_table.h"

namespace qdml::test {

// expected_value(spec, value): checks one numeric parameter's value in the file against the spec.
template <typename ExpectValue>
void expect_mlx_lists(const char* path, const std::vector<ParamSpec>& specs, ExpectValue expected_value) {
  QFile file(path);
  ASSERT_TRUE(file.open(QIODevice::ReadOnly)) << path;
  QDomDocument doc;
  ASSERT_TRUE(doc.setContent(&file));
  const QDomNodeList params = doc.elementsByTagName("Param");
  ASSERT_EQ(params.size(), static_cast<int>(specs.size())) << path;
  const std::map<ParamKind, QString> types = {{ParamKind::Float, "RichFloat"}, {ParamKind::Int, "RichInt"},
                                              {ParamKind::Bool, "RichBool"}, {ParamKind::Enum, "RichEnum"},
                                              {ParamKind::SaveFile, "RichSaveFile"}};
  for (int i = 0; i < params.size(); ++i) {
    const QDomElement p = params.at(i).toElement();
    const ParamSpec& spec = specs[static_cast<size_t>(i)];
    EXPECT_EQ(p.attribute("name").toStdString(), spec.name);
    EXPECT_EQ(p.attribute("type"), types.at(spec.kind)) << spec.name;
    const QString value = p.attribute("value");
    if (spec.kind == ParamKind::Bool) {
      EXPECT_EQ(value == "true", spec.value != 0) << spec.name;
    } else if (spec.kind == ParamKind::SaveFile) {
      EXPECT_EQ(value, "") << spec.name << ": a sample writes no file by default";
      EXPECT_EQ(p.attribute("ext").toStdString(), spec.extension) << spec.name;
    } else {
      expected_value(spec, value.toDouble());
    }
    if (spec.kind == ParamKind::Enum) {
      ASSERT_EQ(p.attribute("enum_cardinality").toInt(), static_cast<int>(spec.items.size()));
      for (size_t k = 0; k < spec.items.size(); ++k)
        EXPECT_EQ(p.attribute(QString("enum_val%1").arg(k)).toStdString(), spec.items[k]);
    }
  }
}

// The 2020.09 plugin holds floats: the script's value and the default agree as floats.
inline void expect_float_default(const ParamSpec& spec, double value) {
  EXPECT_EQ(static_cast<float>(value), static_cast<float>(spec.value)) << spec.name;
}

}  // namespace qdml::test
