// Text inside an XML document (W3C, "Extensible Markup Language 1.0", 2.4): the characters that
// would end an attribute or start markup, written as entities. Used by the SVG writers.
#pragma once

#include <string>

namespace qd::io {

std::string xml_escaped(const std::string& text);

}  // namespace qd::io
