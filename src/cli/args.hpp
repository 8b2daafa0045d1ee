#pragma once
// A small command-line reader: positionals and --name value / --name=value options, each option
// declared by the command so unknown ones are rejected with a clear message.
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace stipple::cli {

class Args {
public:
    // `flags` take no value; `options` take one. Throws stipple::Error on unknown or incomplete options.
    Args(const std::vector<std::string>& argv, const std::set<std::string>& flags,
         const std::set<std::string>& options);

    const std::vector<std::string>& positionals() const { return positionals_; }
    // Fails (stipple::Error) when more than `most` positionals were given, with `usage` (say "render takes at most
    // one MODEL"): naming the flag a surplus one came right after, which takes no value (`--shading yes`).
    void expect_at_most_positionals(size_t most, const std::string& usage) const;
    bool flag(const std::string& name) const { return flags_.count(name) > 0; }
    bool has(const std::string& name) const { return values_.count(name) > 0; }
    std::string get(const std::string& name, const std::string& fallback) const;
    double number(const std::string& name, double fallback) const;
    long long integer(const std::string& name, long long fallback) const;
    glm::vec3 vec3(const std::string& name, glm::vec3 fallback) const;
    // A colour: #rrggbb (or #rgb) as web pages write it, or R,G,B each in 0..1 as scene files do.
    glm::vec3 colour(const std::string& name, glm::vec3 fallback) const;

private:
    std::vector<std::string> positionals_;
    std::vector<std::string> flag_before_;  // by positional: the flag right before it, else empty
    std::set<std::string> flags_;
    std::map<std::string, std::string> values_;
};

// --device: the index of a Vulkan device (render --list-devices), or -1 when not given (the default one).
// Out of 0..64 it is an error with the value as typed (an index past the devices is the context's error).
int device_index(const Args& args);

// The comma-separated entries of an option's value; an empty entry is an error naming `option`.
std::vector<std::string> split_list(const std::string& option, const std::string& list);

}  // namespace stipple::cli
