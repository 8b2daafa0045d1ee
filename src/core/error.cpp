#include "core/error.hpp"

namespace stipple {

void fail_file(const std::string& path, const std::string& problem) { throw Error(path + ": " + problem); }

void fail(const std::string& message) { throw Error(message); }

}  // namespace stipple
