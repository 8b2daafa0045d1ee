#pragma once
// Small pieces the model loaders share.
#include <string>

#include "core/error.hpp"

namespace stipple {

// The whole file in one read (the parsers then work on plain memory); errors name the file.
std::string read_file(const std::string& path);

// one_line (core/error.hpp): library messages may span lines and quote file bytes; ours are one line.

}  // namespace stipple
