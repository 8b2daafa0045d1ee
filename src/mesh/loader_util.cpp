#include "mesh/loader_util.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "core/error.hpp"

namespace stipple {

std::string read_file(const std::string& path) {
    std::error_code ec;
    const uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) fail_file(path, "cannot read: " + ec.message());
    std::string data(size, '\0');  // before the file is opened: memory that runs out leaves no handle open
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) fail_file(path, std::string("cannot open: ") + std::strerror(errno));
    const size_t got = std::fread(data.data(), 1, data.size(), f);
    std::fclose(f);
    if (got != size) fail_file(path, "read error after " + std::to_string(got) + " of " + std::to_string(size) + " bytes");
    return data;
}


}  // namespace stipple
