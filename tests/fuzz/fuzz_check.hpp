#pragma once
// What every harness asserts about one input: the reader either returns a well-formed result or throws
// stipple::Error with one printable line "<name>: <problem>". Anything else is a finding: a crash, a
// sanitizer report, another exception escaping (libFuzzer reports it as a deadly signal), a leak, a
// hang or an allocation over the limit; a broken contract aborts with the offending message.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/error.hpp"
#include "mesh/mesh.hpp"

namespace stipple::fuzz {

[[noreturn]] inline void contract_broken(const std::string& what) {
    std::fprintf(stderr, "fuzz contract broken: %s\n", what.c_str());
    std::abort();
}

inline void check_message(const stipple::Error& e, const std::string& name) {
    const std::string message = e.what();
    if (message.rfind(name + ": ", 0) != 0) contract_broken("message does not start with the file name: " + message);
    for (char c : message)
        if (static_cast<unsigned char>(c) < 0x20) contract_broken("message is not one printable line: " + message);
    // An internal check names no problem of the file: a valid file the loaders disagree on (a two-sided sheet
    // the static loader split and the animated one did not, found by review on 2026-12-04) or a bug.
    // (Right after the name only: a message may quote the file's bytes, which may read ": internal".)
    if (message.rfind(name + ": internal", 0) == 0) contract_broken("an internal check failed: " + message);
}

// The promises of load_mesh (mesh.hpp): indices in range, finite positions, unit normals.
inline void check_mesh(const Mesh& mesh) {
    if (mesh.indices.empty() || mesh.indices.size() % 3 != 0) contract_broken("index count");
    if (mesh.normals.size() != mesh.positions.size()) contract_broken("normal count");
    for (uint32_t i : mesh.indices)
        if (i >= mesh.positions.size()) contract_broken("index out of range");
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        const glm::vec3 p = mesh.positions[v], n = mesh.normals[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) contract_broken("position not finite");
        if (std::fabs(glm::length(n) - 1.0f) > 1e-3f) contract_broken("normal not unit length");
    }
}

}  // namespace stipple::fuzz
