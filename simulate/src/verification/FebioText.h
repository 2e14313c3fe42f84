#pragma once
// Numbers and comments as an FEBio export writes them: numbers in the file with 17
// significant digits (they read back as the same double), in messages and comments with 4;
// comments as XML allows them in the file's ISO-8859-1 (ASCII, no "--").
#include <string>

namespace vesica::simulate {

std::string febio_number(double value);
std::string febio_message_number(double value);
// "<indent><!-- text -->\n" with "§" written "section" and every "--" as "-".
std::string febio_comment(const std::string& text, const std::string& indent = "");

}  // namespace vesica::simulate
