// The regression guard: this run's speeds against an earlier results.json.
#include "core/printf_string.hpp"
#include "bench/bench_compare.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/error.hpp"

namespace stipple::bench {

namespace {

using nlohmann::json;

// A member that must be there with the given kind; anything else means the file is not a results.json.
const json& member(const json& object, const char* key, json::value_t kind, const std::string& name,
                   const std::string& where) {
    if (!object.is_object() || !object.contains(key))
        fail_file(name, "not a stipple bench results.json (" + where + " has no \"" + key + "\")");
    const json& value = object.at(key);
    const bool number = kind == json::value_t::number_float;
    if (number ? !value.is_number() : value.type() != kind)
        fail_file(name, "not a stipple bench results.json (\"" + std::string(key) + "\" of " + where + " has the wrong type)");
    return value;
}

double number(const json& object, const char* key, const std::string& name, const std::string& where) {
    return member(object, key, json::value_t::number_float, name, where).get<double>();
}

// A speed of 0 is a cell that measured nothing (it has no ratio to compare and is left out); a negative
// one is no speed at all, and read as one it made every later run look faster or slower at random.
void add_speed(std::map<std::string, double>& speeds, const std::string& key, double speed, const std::string& name) {
    if (speed < 0.0) fail_file(name, "\"" + key + "\" has the speed " + printf_string("%g", speed) + "; a speed cannot be negative");
    if (speed == 0.0) return;
    if (!speeds.emplace(key, speed).second) fail_file(name, "\"" + key + "\" appears twice");
}

// The plot-order row's entries: dots per second of ordering, where both figures are there.
void plot_order_speeds(const json& root, std::map<std::string, double>& speeds, const std::string& name) {
    if (!root.contains("plot_order") || root["plot_order"].is_null()) return;
    const json& row = member(root, "plot_order", json::value_t::object, name, "the file");
    for (const auto& [what, entry] : row.items()) {
        if (!entry.is_object()) continue;  // skipped in that run (null), or its note
        const std::string where = "plot_order." + what;
        const double dots = number(entry, "dots", name, where), seconds = number(entry, "order_seconds", name, where);
        if (seconds > 0.0) add_speed(speeds, "plot order / " + what, dots / seconds, name);
    }
}

}  // namespace

std::map<std::string, double> read_speeds(const std::string& json_text, const std::string& name) {
    json root;
    try {
        root = json::parse(json_text);
    } catch (const json::exception& e) {
        std::string what = e.what();
        std::replace(what.begin(), what.end(), '\n', ' ');
        fail_file(name, "not JSON: " + what);
    }
    std::map<std::string, double> speeds;
    for (const json& model : member(root, "models", json::value_t::array, name, "the file")) {
        const std::string model_name = member(model, "name", json::value_t::string, name, "a model").get<std::string>();
        const std::string where = "model '" + model_name + "'";
        for (const json& cell : member(model, "cells", json::value_t::array, name, where)) {
            const std::string column = member(cell, "column", json::value_t::string, name, where).get<std::string>();
            add_speed(speeds, model_name + " / " + column, number(cell, "median_fps", name, where + " " + column), name);
        }
        const double seconds = number(model, "preprocessing_seconds", name, where);
        const double candidates = number(model, "candidate_stipples", name, where);
        if (seconds > 0.0) add_speed(speeds, model_name + " / generation", candidates / seconds, name);
    }
    plot_order_speeds(root, speeds, name);
    return speeds;
}

std::string read_results_file(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) fail_file(path, "is a folder: --compare takes an earlier run's results.json");
    const auto status = std::filesystem::status(path, ec);
    if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
        fail_file(path, "is not a regular file: --compare takes an earlier run's results.json");  // a FIFO waited for ever
    // A run's results are tens of kilobytes, up to ~100 MB with --frames at its 100,000 (each cell lists its
    // frame times); /dev/zero-like sizes are not read into memory.
    constexpr uintmax_t kMostBytes = uintmax_t(1) << 30;
    if (const uintmax_t size = std::filesystem::file_size(path, ec); !ec && size > kMostBytes)
        fail_file(path, "is " + std::to_string(size >> 20) + " MiB: not a bench run's results.json");
    std::ifstream in(path, std::ios::binary);
    if (!in) fail_file(path, "cannot read the results to compare with (no such file?)");
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) fail_file(path, "read failed");
    read_speeds(text.str(), path);
    return text.str();
}

std::map<std::string, double> read_speeds_file(const std::string& path) {
    return read_speeds(read_results_file(path), path);
}

namespace {

// A field's value as the report prints it, or "" where the file lacks it (an older run) or holds no plain
// value there (an array or object, which dump() printed recursively: 100k nested brackets overflowed the stack).
std::string field_text(const json& object, const char* key) {
    if (!object.is_object() || !object.contains(key)) return "";
    const json& value = object.at(key);
    if (value.is_string()) return one_line(value.get<std::string>().substr(0, 200));
    return value.is_number() || value.is_boolean() ? value.dump() : "";
}

// What a model's speeds were measured on: its source and size (where the file says both).
std::map<std::string, std::string> model_geometry(const json& root) {
    std::map<std::string, std::string> out;
    for (const json& model : root.at("models")) {
        const std::string source = field_text(model, "source"), triangles = field_text(model, "triangles");
        if (!source.empty() && !triangles.empty())
            out[model.at("name").get<std::string>()] = source + ", " + triangles + " triangles";
    }
    return out;
}

}  // namespace

Comparison compare_runs(const std::string& old_text, const std::string& old_name, const std::string& new_text,
                        double threshold) {
    std::map<std::string, double> old_speeds = read_speeds(old_text, old_name), new_speeds = read_speeds(new_text, "this run");
    const json old_root = json::parse(old_text), new_root = json::parse(new_text);
    std::vector<std::string> settings;
    for (const char* key : {"width", "height", "queued_frames", "timed_frames", "warmup_frames", "quick", "device",
                            "depth_cull", "depth_raster"}) {
        const std::string was = field_text(old_root, key), now = field_text(new_root, key);
        if (!was.empty() && !now.empty() && was != now) settings.push_back(std::string(key) + " " + was + " -> " + now);
    }
    std::vector<std::string> not_comparable;
    const auto old_geometry = model_geometry(old_root), new_geometry = model_geometry(new_root);
    for (const auto& [model, was] : old_geometry) {
        const auto now = new_geometry.find(model);
        if (now == new_geometry.end() || now->second == was) continue;
        not_comparable.push_back(model + ": " + was + " -> " + now->second);
        const std::string prefix = model + " / ";
        for (auto* speeds : {&old_speeds, &new_speeds})
            std::erase_if(*speeds, [&](const auto& entry) { return entry.first.rfind(prefix, 0) == 0; });
    }
    // The plot order's speed depends on how many dots it orders (--plot-dots): 40,000 against 1,000 read
    // as a 30% regression.
    const auto plot_dots = [](const json& root, const std::string& what) {
        if (!root.contains("plot_order") || !root["plot_order"].is_object()) return std::string();
        return field_text(root["plot_order"].value(what, json()), "dots");
    };
    if (old_root.contains("plot_order") && old_root["plot_order"].is_object())
        for (const auto& [what, entry] : old_root["plot_order"].items()) {
            const std::string was = plot_dots(old_root, what), now = plot_dots(new_root, what);
            if (was.empty() || now.empty() || was == now) continue;
            not_comparable.push_back("plot order / " + what + ": " + was + " -> " + now + " dots");
            for (auto* speeds : {&old_speeds, &new_speeds}) speeds->erase("plot order / " + what);
        }
    Comparison c = compare_speeds(old_speeds, new_speeds, threshold);
    c.settings = std::move(settings);
    c.not_comparable = std::move(not_comparable);
    return c;
}

Comparison compare_speeds(const std::map<std::string, double>& old_speeds, const std::map<std::string, double>& new_speeds,
                          double threshold) {
    Comparison c;
    for (const auto& [key, old_speed] : old_speeds) {
        auto found = new_speeds.find(key);
        if (found == new_speeds.end()) {
            c.only_in_old.push_back(key);
            continue;
        }
        const SpeedChange change{key, old_speed, found->second};
        if (c.compared == 0 || change.loss() > c.worst.loss()) c.worst = change;
        ++c.compared;
        if (change.loss() > threshold) c.slower.push_back(change);
    }
    for (const auto& entry : new_speeds)
        if (!old_speeds.count(entry.first)) c.only_in_new.push_back(entry.first);
    std::stable_sort(c.slower.begin(), c.slower.end(),
                     [](const SpeedChange& a, const SpeedChange& b) { return a.loss() > b.loss(); });
    return c;
}

std::string comparison_text(const Comparison& c, const std::string& old_name, double threshold) {
    std::string text;
    auto change_text = [](const SpeedChange& s) {
        return printf_string("%s %+.1f%% (%.4g -> %.4g)", s.key.c_str(), -100.0 * s.loss(), s.old_speed, s.new_speed);
    };
    if (!c.settings.empty()) {
        text += "  the runs were made differently, so their speeds differ for that too:";
        for (size_t i = 0; i < c.settings.size(); ++i) text += (i ? "; " : " ") + c.settings[i];
        text += "\n";
    }
    for (const std::string& what : c.not_comparable)
        text += "  not comparable (other " + std::string(what.rfind("plot order", 0) == 0 ? "dot count" : "geometry") +
                "), left out: " + what + "\n";
    for (const SpeedChange& s : c.slower) text += "  slower: " + change_text(s) + "\n";
    for (const std::string& key : c.only_in_old) text += "  missing in this run: " + key + "\n";
    for (const std::string& key : c.only_in_new) text += "  missing in " + old_name + ": " + key + "\n";
    text += printf_string("compared with %s: %zu cells compared, %zu slower by more than %.0f%%", old_name.c_str(), c.compared,
                   c.slower.size(), 100.0 * threshold);
    if (c.compared > 0) text += ", the worst: " + change_text(c.worst);
    if (!c.only_in_old.empty() || !c.only_in_new.empty())
        text += printf_string("; %zu only in %s, %zu only in this run", c.only_in_old.size(), old_name.c_str(), c.only_in_new.size());
    return text + "\n";
}

}  // namespace stipple::bench
