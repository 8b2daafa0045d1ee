#pragma once
// Small pieces the model loaders share.
#include <string>

namespace stipple {

// The whole file in one read (the parsers then work on plain memory); errors name the file.
std::string read_file(const std::string& path);

// Library messages may span lines and quote file bytes; ours are one printable line.
std::string one_line(const std::string& text);

}  // namespace stipple
