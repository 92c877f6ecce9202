// Escaping text for XML, shared by every writer of XML (SVG plots, robot descriptions).
#ifndef HULLPACK_TOOLS_COMMON_XML_ESCAPE_H_
#define HULLPACK_TOOLS_COMMON_XML_ESCAPE_H_

#include <string>

namespace hullpack {

// Text with &, <, >, " and ' escaped for XML character data and attribute values.
std::string XmlEscape(const std::string& text);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_COMMON_XML_ESCAPE_H_
