#include "bench/model_set.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <meshoptimizer.h>

#include "bench/bench_output.hpp"
#include "mesh/mesh_ops.hpp"
#include "mesh/orientation.hpp"
#include "mesh/ply_writer.hpp"
#include "core/timing.hpp"
#include "bench/table1.hpp"
#include "core/error.hpp"
#include "core/timing.hpp"
#include "mesh/load_mesh.hpp"
#include "mesh/primitives.hpp"

namespace stipple::bench {

namespace fs = std::filesystem;

// Each row from a scan of a similar size where one exists; the larger rows by subdividing a scan
// (twice for the ogre and the horse: once is not enough) and simplifying back down to the row.
const std::vector<Recipe> kRecipes = {
    {"horse", "horse.ply", true},          // 96,966 -> simplified
    {"low-res dragon", "igea.ply"},        // 268,686 -> simplified
    {"bunny", "stanford-bunny.obj"},       // 69,451: as is
    {"skeleton1", "ogre.obj"},             // 124,008: as is (-0.008%)
    {"skeleton2", "ogre.obj"},             // x16 = 1,984,128 -> simplified
    {"hand", "horse.ply", true},           // x16 = 1,551,456 -> simplified
    {"dragon", "igea.ply"},                // x4 = 1,074,744 -> simplified
};

namespace {

std::string slug(const std::string& name) {
    std::string s;
    for (char c : name) s += (c == ' ' || c == '/') ? '-' : c;
    return s;
}

const Recipe& find_recipe(const std::string& row) {
    for (const Recipe& r : kRecipes)
        if (row == r.row) return r;
    fail("unknown model '" + row + "' (the rows of Table 1 are: " + paper_row_names() + ")");
}

// What decides whether a cached model is current: the derivation, the library, the row, the source file.
std::string key_header(const PaperRow& row, const fs::path& source) {
    std::error_code ec;
    auto size = fs::file_size(source, ec);
    auto mtime = fs::last_write_time(source, ec).time_since_epoch().count();
    std::ostringstream key;
    key << "stipple bench model v" << kDerivationVersion << "\n"
        << "meshoptimizer " << MESHOPTIMIZER_VERSION << "\n"
        << "row " << row.name << " " << row.polygons << "\n"
        << "source " << fs::absolute(source).lexically_normal().string() << " " << size << " " << mtime << "\n";
    return key.str();
}

void write_text_atomically(const fs::path& path, const std::string& text) {
    fs::path temporary = path;
    temporary += ".tmp" + std::to_string(::getpid());
    {
        std::ofstream out(temporary, std::ios::trunc);
        out << text;
        if (!out.flush()) fail_file(temporary.string(), "cannot write");
    }
    std::error_code ec;
    fs::rename(temporary, path, ec);
    if (ec) fail_file(path.string(), "cannot move the new file into place: " + ec.message());
}

// The cached result when the key file matches: triangles, how it was made, and the file to load.
bool read_cached(const fs::path& key_path, const std::string& header, ModelEntry& entry, const fs::path& ply) {
    std::ifstream in(key_path);
    if (!in) return false;
    std::stringstream ss;
    ss << in.rdbuf();
    std::string text = ss.str();
    if (text.compare(0, header.size(), header) != 0) return false;
    std::istringstream rest(text.substr(header.size()));
    std::string word, kind, source;
    size_t triangles = 0;
    if (!(rest >> word >> triangles >> kind) || word != "result") return false;
    std::getline(rest >> std::ws, source);
    if (source.empty()) return false;
    if (kind == "derived") {
        if (!fs::is_regular_file(ply)) return false;
        entry.path = ply;
    } else if (kind != "as-is") {
        return false;
    }
    entry.triangles = triangles;
    entry.source = source;
    return true;
}

void derive(const PaperRow& row, const Recipe& recipe, const fs::path& source_path, const fs::path& ply,
            ModelEntry& entry, const std::function<void(const std::string&)>& log) {
    auto start = std::chrono::steady_clock::now();
    Mesh mesh = load_mesh(source_path.string());
    const size_t original = mesh.triangle_count();
    std::string how = std::string(recipe.source) + " (" + with_commas(original) + ")";
    if (within(original, row.polygons, kRowTolerance) && !recipe.z_up && signed_volume(mesh) >= 0.0) {
        entry.triangles = original;
        entry.source = how + ", as is";
        entry.path = source_path;
    } else {
        mesh = weld_positions(mesh);
        if (recipe.z_up) {  // (x, y, z) -> (x, z, -y): a rotation about X taking +Z to +Y
            for (glm::vec3& p : mesh.positions) p = glm::vec3(p.x, p.z, -p.y);
            how += ", turned Y-up";
        }
        // (load_mesh has already turned inside-out scans outward.)
        int subdivisions = 0;
        while (double(mesh.triangle_count()) < double(row.polygons) * (1.0 - kRowTolerance)) {
            mesh = subdivide_midpoints(mesh);
            ++subdivisions;
        }
        if (subdivisions > 0) how += ", subdivided x" + std::to_string(1 << (2 * subdivisions)) + " to " + with_commas(mesh.triangle_count());
        SimplifyResult simplified = simplify_to(mesh, row.polygons, kRowTolerance);
        how += ", meshopt " + simplified.method;
        // Through a temporary file: a run killed while writing left a truncated PLY that every later run
        // failed to load (the key file said it was there).
        const fs::path part = ply.string() + ".part" + std::to_string(::getpid());
        write_ply_binary(part.string(), simplified.mesh);
        std::error_code ec;
        fs::rename(part, ply, ec);
        if (ec) fail_file(ply.string(), "cannot store the derived model: " + ec.message());
        entry.triangles = simplified.mesh.triangle_count();
        entry.source = how;
        entry.path = ply;
    }
    entry.derived_now = true;
    if (log) {
        char line[512];
        std::snprintf(line, sizeof line, "derived %s: %s -> %s triangles (row %s) in %.1f s", row.name, how.c_str(),
                      with_commas(entry.triangles).c_str(), with_commas(row.polygons).c_str(), seconds_since(start));
        log(line);
    }
}

}  // namespace

fs::path ModelSetOptions::default_models_dir() {
    if (const char* env = std::getenv("STIPPLE_SHARED_MODELS"); env && *env) return env;
    return (fs::path(STIPPLE_SOURCE_DIR) / ".." / "shared" / "models").lexically_normal();
}

fs::path ModelSetOptions::default_cache_dir() {
    if (const char* env = std::getenv("STIPPLE_CACHE_DIR"); env && *env) return fs::path(env) / "bench-models";
    // The build folder: the compiled shaders live in <build>/shaders (third_party_config/Shaders.cmake).
    return fs::path(STIPPLE_SHADER_DIR).parent_path() / "bench-models";
}

std::vector<std::string> rows_without_scans(const fs::path& models_dir, const std::vector<std::string>& rows) {
    // Only the rows run: --models horse with horse.ply alone said every row was a sphere.
    std::vector<std::string> missing;
    for (const Recipe& r : kRecipes)
        if ((rows.empty() || std::find(rows.begin(), rows.end(), r.row) != rows.end()) &&
            !fs::is_regular_file(models_dir / r.source))
            missing.push_back(r.row);
    return missing;
}

bool scans_available(const fs::path& models_dir, const std::vector<std::string>& rows) {
    return rows_without_scans(models_dir, rows).empty();
}

std::vector<ModelEntry> prepare_model_set(const ModelSetOptions& options) {
    std::vector<std::string> rows = options.only;
    if (rows.empty())
        for (const PaperRow& row : kPaperTable) rows.push_back(row.name);
    std::vector<ModelEntry> entries;
    for (const std::string& name : rows) {
        const Recipe& recipe = find_recipe(name);
        const PaperRow& row = *find_paper_row(name);
        ModelEntry entry;
        entry.name = row.name;
        entry.target = row.polygons;
        const fs::path source_path = options.models_dir / recipe.source;
        if (!fs::is_regular_file(source_path)) {
            entry.procedural = true;
            entry.triangles = make_uv_sphere(row.polygons).triangle_count();
            entry.source = std::string("procedural UV sphere (") + recipe.source + " not found)";
            entries.push_back(entry);
            continue;
        }
        const fs::path ply = options.cache_dir / (slug(row.name) + ".ply");
        const fs::path key = options.cache_dir / (slug(row.name) + ".key");
        const std::string header = key_header(row, source_path);
        if (!read_cached(key, header, entry, ply)) {
            if (options.log) options.log("deriving " + name + " from " + recipe.source + " into " + options.cache_dir.string());
            std::error_code ec;
            fs::create_directories(options.cache_dir, ec);
            if (ec) fail_file(options.cache_dir.string(), "cannot create the model cache: " + ec.message());
            derive(row, recipe, source_path, ply, entry, options.log);
            bool as_is = entry.path == source_path;
            write_text_atomically(key, header + "result " + std::to_string(entry.triangles) + " " +
                                           (as_is ? "as-is" : "derived") + " " + entry.source + "\n");
        } else if (entry.path.empty()) {
            entry.path = source_path;  // an as-is row
        }
        entries.push_back(entry);
    }
    return entries;
}

Mesh load_model(const ModelEntry& entry) {
    if (entry.procedural) {
        Mesh mesh = make_uv_sphere(entry.target);
        mesh.source = "uv_sphere(" + std::to_string(entry.target) + ")";
        return mesh;
    }
    return load_mesh_for_drawing(entry.path.string());
}

Mesh load_model(ModelEntry& entry, const ModelSetOptions& options) {
    std::error_code ec;  // the same folder however written (a trailing slash, a relative path)
    const bool derived = !entry.procedural && fs::equivalent(entry.path.parent_path(), options.cache_dir, ec);
    if (!derived) return load_model(entry);
    try {
        return load_model(entry);
    } catch (const Error& e) {
        if (options.log) options.log(std::string("NOTE: ") + e.what() + ": deriving it again");
        fs::remove(options.cache_dir / (slug(entry.name) + ".key"), ec);
        fs::remove(entry.path, ec);
        ModelSetOptions again = options;
        again.only = {entry.name};
        entry = prepare_model_set(again).at(0);
        return load_model(entry);
    }
}

}  // namespace stipple::bench
