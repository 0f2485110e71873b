// Text inside XML (SVG pictures, the JUnit file): the five characters XML reserves in
// attributes and text, escaped.
#pragma once

#include <string>

namespace bb {

/// `s` with &, <, > and " escaped for XML text and attributes.
std::string escape_xml(const std::string& s);

}  // namespace bb
