#include "params/param_docs.hpp"

#include <sstream>

#include "params/param_table.hpp"

namespace stipple {

namespace {

constexpr size_t kOptionColumn = 26;  // where the help text starts
constexpr size_t kLineWidth = 100;

std::string option_spelling(const ParamSpec& spec) {
    const std::string cli = spec.cli;
    switch (spec.type) {
        case ParamType::Bool: return "--" + cli + ", --no-" + cli;
        case ParamType::Choice: return "--" + cli + " NAME";
        case ParamType::Int: return "--" + cli + " N";
        case ParamType::Float: break;
    }
    return "--" + cli + " F";
}

std::string default_text(const ParamSpec& spec) {
    const double value = spec.get(ObjectParams{});
    if (spec.type == ParamType::Bool) return value != 0.0 ? "on" : "off";
    return format_param_value(spec, value);
}

// Words of `text` wrapped at kLineWidth, every line indented to the help column.
void wrap(std::ostringstream& out, const std::string& first, const std::string& text) {
    std::string line = "  " + first;
    if (line.size() + 1 >= kOptionColumn) {
        out << line << "\n";
        line.clear();
    }
    line.resize(kOptionColumn, ' ');
    size_t column_used = kOptionColumn;
    std::istringstream words(text);
    std::string word;
    bool first_word = true;
    while (words >> word) {
        if (!first_word && column_used + 1 + word.size() > kLineWidth) {
            out << line << "\n";
            line = std::string(kOptionColumn, ' ');
            column_used = kOptionColumn;
            first_word = true;
        }
        if (!first_word) {
            line += ' ';
            ++column_used;
        }
        line += word;
        column_used += word.size();
        first_word = false;
    }
    out << line << "\n";
}

}  // namespace

std::string param_help_text() {
    std::ostringstream out;
    const char* section = nullptr;
    for (const ParamSpec& spec : param_table()) {
        if (!section || std::string(section) != spec.section) {
            section = spec.section;
            out << " " << section << ":\n";
        }
        std::string text = spec.help;
        if (spec.alias)
            text += " (" + param_range_text(spec) + ")";
        else if (spec.type == ParamType::Bool)
            text += " (default " + default_text(spec) + ")";
        else
            text += " (" + param_range_text(spec) + "; default " + default_text(spec) + ")";
        wrap(out, option_spelling(spec), text);
    }
    return out.str();
}

std::string param_markdown_table() {
    std::ostringstream out;
    out << "| scene key | command line | range | default | a change | meaning |\n";
    out << "|---|---|---|---|---|---|\n";
    for (const ParamSpec& spec : param_table()) {
        std::string cli = "`--" + std::string(spec.cli) + "`";
        if (spec.type == ParamType::Bool) cli += ", `--no-" + std::string(spec.cli) + "`";
        const std::string effect = spec.effect == ParamEffect::Regenerate ? "new stipples" : "next frame";
        // In the scene file's words, as the range column gives them ("on" read as a string there).
        const std::string deflt = spec.alias                        ? ""
                                  : spec.type == ParamType::Bool ? (spec.get(ObjectParams{}) != 0.0 ? "true" : "false")
                                                                 : default_text(spec);
        out << "| `" << spec.key << "` | " << cli << " | " << param_range_text(spec) << " | " << deflt << " | "
            << effect << " | " << spec.help << (spec.alias ? " (alias, never written)" : "") << " |\n";
    }
    return out.str();
}

std::string param_scene_example() {
    std::ostringstream out;
    std::string line = "\"params\": {";
    bool first = true;
    for (const ParamSpec& spec : param_table()) {
        if (spec.alias) continue;
        std::string value = format_param_value(spec, spec.get(ObjectParams{}));
        if (spec.type == ParamType::Choice) value = "\"" + value + "\"";
        const std::string item = (first ? "" : ", ") + std::string("\"") + spec.key + "\": " + value;
        if (line.size() + item.size() > 84) {
            out << line << (first ? "" : ",") << "\n";
            line = "           " + item.substr(first ? 0 : 2);
        } else {
            line += item;
        }
        first = false;
    }
    out << line << "}";
    return out.str();
}

}  // namespace stipple
