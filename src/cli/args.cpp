#include "cli/args.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <sstream>

#include "core/decimal.hpp"
#include "core/error.hpp"

namespace stipple::cli {

Args::Args(const std::vector<std::string>& argv, const std::set<std::string>& flags,
           const std::set<std::string>& options) {
    for (size_t i = 0; i < argv.size(); ++i) {
        const std::string& arg = argv[i];
        if (arg.size() < 2 || arg[0] != '-' || (arg.size() > 1 && (std::isdigit(arg[1]) || arg[1] == '.'))) {
            const std::string before = i > 0 && flags.count(argv[i - 1]) ? argv[i - 1] : std::string();
            // A switch's value, as other tools take one (`--shading yes`): it would be read as a model ("yes: no
            // such file"), not a word about the option.
            static const std::set<std::string> kSwitchWords = {"yes", "no", "true", "false", "on", "off", "0", "1"};
            std::error_code ec;
            if (!before.empty() && kSwitchWords.count(arg) && !std::filesystem::exists(arg, ec))
                fail("option " + before + " takes no value (got '" + arg + "' after it; see --help)");
            positionals_.push_back(arg);
            flag_before_.push_back(before);
            continue;
        }
        std::string name = arg;
        std::optional<std::string> value;
        if (size_t eq = arg.find('='); eq != std::string::npos) {
            name = arg.substr(0, eq);
            value = arg.substr(eq + 1);
        }
        if (flags.count(name)) {
            if (value) fail("option " + name + " takes no value");
            flags_.insert(name);
        } else if (options.count(name)) {
            if (!value) {
                if (i + 1 >= argv.size()) fail("option " + name + " needs a value");
                value = argv[++i];
            }
            // Given twice, one of them would be dropped without a word.
            if (auto earlier = values_.find(name); earlier != values_.end())
                fail("option " + name + " given twice (" + earlier->second + " and " + *value + ")");
            values_[name] = *value;
        } else {
            fail("unknown option " + name + " (see --help)");
        }
    }
}

void Args::expect_at_most_positionals(size_t most, const std::string& usage) const {
    if (positionals_.size() <= most) return;
    // A word right after a switch that names no file is the likely stray (`--shading softly model.obj`); a model
    // there is not (`--no-shading bunny.obj dragon.obj`).
    for (size_t i = 0; i < positionals_.size(); ++i) {
        std::error_code ec;
        if (!flag_before_[i].empty() && !std::filesystem::exists(positionals_[i], ec))
            fail("'" + positionals_[i] + "' after " + flag_before_[i] + ", which takes no value (" + usage + "; see stipple --help)");
    }
    fail(usage + " (see stipple --help)");
}

std::string Args::get(const std::string& name, const std::string& fallback) const {
    auto it = values_.find(name);
    return it == values_.end() ? fallback : it->second;
}

double Args::number(const std::string& name, double fallback) const {
    auto it = values_.find(name);
    if (it == values_.end()) return fallback;
    const std::optional<double> value = parse_decimal(it->second);
    if (!value) fail(name + ": '" + it->second + "' is not a finite number");
    return *value;
}

long long Args::integer(const std::string& name, long long fallback) const {
    auto it = values_.find(name);
    if (it == values_.end()) return fallback;
    const std::optional<int64_t> value = parse_decimal_integer(it->second);
    if (!value) fail(name + ": '" + it->second + "' is not an integer");
    return *value;
}

glm::vec3 Args::vec3(const std::string& name, glm::vec3 fallback) const {
    auto it = values_.find(name);
    if (it == values_.end()) return fallback;
    const std::string& text = it->second;
    glm::dvec3 v;
    size_t start = 0;
    for (int i = 0; i < 3; ++i) {
        const size_t comma = i < 2 ? text.find(',', start) : text.size();
        const std::optional<double> part =
            comma == std::string::npos ? std::nullopt : parse_decimal(std::string_view(text).substr(start, comma - start));
        if (!part || (i == 2 && text.find(',', start) != std::string::npos))
            fail(name + ": '" + text + "' is not three numbers " +
                 (name == "--ink" || name == "--paper" ? "R,G,B" : "X,Y,Z"));
        v[i] = *part;
        start = comma + 1;
    }
    // Read in double so that 1e300 is named for what it is, not "not a number".
    if (glm::any(glm::greaterThan(glm::abs(v), glm::dvec3(std::numeric_limits<float>::max()))))
        fail(name + ": '" + it->second + "' has a number beyond single precision (3.4e+38)");
    return glm::vec3(v);
}

glm::vec3 Args::colour(const std::string& name, glm::vec3 fallback) const {
    auto it = values_.find(name);
    if (it == values_.end()) return fallback;
    const std::string& text = it->second;
    // Without commas it is hex digits, with or without the '#' (which a shell may need quoted), but decimal
    // digits alone need it: `--ink 100` read as #110000 would be a dark red nobody asked for.
    if (text.find(',') == std::string::npos) {
        const bool hash = !text.empty() && text[0] == '#';
        const std::string digits = hash ? text.substr(1) : text;
        if (!hash && !digits.empty() && digits.find_first_not_of("0123456789") == std::string::npos)
            fail(name + ": '" + text + "' is not a colour: write #" + text + " for hex digits, or R,G,B each in 0..1");
        const bool hex = !digits.empty() && digits.find_first_not_of("0123456789abcdefABCDEF") == std::string::npos;
        if (!hex || (digits.size() != 6 && digits.size() != 3))
            fail(name + ": '" + text + "' is not a colour (#rrggbb, #rgb, or R,G,B each in 0..1)");
        const size_t width = digits.size() / 3;  // 2 or 1 hex digits a channel; #abc is #aabbcc
        glm::vec3 c;
        for (int i = 0; i < 3; ++i) {
            const unsigned value = unsigned(std::stoul(digits.substr(size_t(i) * width, width), nullptr, 16));
            c[i] = float(width == 2 ? value : value * 17u) / 255.0f;
        }
        return c;
    }
    const glm::vec3 c = vec3(name, fallback);
    for (int i = 0; i < 3; ++i)
        if (!(c[i] >= 0.0f && c[i] <= 1.0f))
            fail(name + ": '" + text + "' is not a colour: each of R,G,B must be in 0..1 (or give #rrggbb)");
    return c;
}

int device_index(const Args& args) {
    if (!args.has("--device")) return -1;
    const long long index = args.integer("--device", -1);
    if (index < 0 || index > 64)
        fail("--device = " + args.get("--device", "") + " is not a device index (render --list-devices lists them)");
    return int(index);
}

std::vector<std::string> split_list(const std::string& option, const std::string& list) {
    std::vector<std::string> items;
    size_t start = 0;
    while (start <= list.size()) {
        size_t end = list.find(',', start);
        if (end == std::string::npos) end = list.size();
        std::string item = list.substr(start, end - start);
        if (item.empty()) fail(option + " '" + list + "' has an empty entry");
        items.push_back(item);
        start = end + 1;
    }
    return items;
}

}  // namespace stipple::cli
