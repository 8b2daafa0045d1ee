#include "stipple/stipple_cache.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

#include "core/hash.hpp"
#include "params/param_table.hpp"
#include "stipple/selection_order.hpp"

namespace stipple {

namespace {

constexpr uint64_t kMagic = 0x5350495453454C50ull;  // "PLESTIPS"
constexpr uint32_t kVersion = 4;  // 2: the polygons' selection values follow first[]; 4: values uniform per area class

struct Header {
    uint64_t magic;
    uint32_t version;
    uint32_t triangles;
    uint64_t key;
    uint64_t stipples;
    double density_per_area;
    double poisson_radius;
};

uint64_t hash_bytes(uint64_t h, const void* data, size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    uint64_t word = 0;
    size_t i = 0;
    for (; i + 8 <= bytes; i += 8) {
        std::memcpy(&word, p + i, 8);
        h = mix64(h ^ word);
    }
    word = 0;
    std::memcpy(&word, p + i, bytes - i);
    return mix64(h ^ word ^ (uint64_t(bytes) << 56));
}

std::filesystem::path entry_path(const std::filesystem::path& dir, uint64_t key) {
    char name[32];
    std::snprintf(name, sizeof(name), "%016llx.stipples", static_cast<unsigned long long>(key));
    return dir / name;
}

}  // namespace

std::filesystem::path default_stipple_cache_dir() {
    if (const char* dir = std::getenv("STIPPLE_CACHE_DIR")) return std::filesystem::path(dir) / "stipples";
    if (const char* xdg = std::getenv("XDG_CACHE_HOME")) return std::filesystem::path(xdg) / "stipple" / "stipples";
    if (const char* home = std::getenv("HOME")) return std::filesystem::path(home) / ".cache" / "stipple" / "stipples";
    return std::filesystem::temp_directory_path() / "stipple-cache" / "stipples";
}

uint64_t stipple_cache_key(const Mesh& mesh, const GenerationParams& params) {
    uint64_t h = mix64(kMagic ^ kVersion);
    h = hash_bytes(h, mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3));
    h = hash_bytes(h, mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t));
    // The parameters that shape generation, as the parameter table marks them, and the reference view.
    std::vector<double> values = generation_values(params);
    values.push_back(kReferenceHeight);
    return hash_bytes(h, values.data(), values.size() * sizeof(double));
}

std::optional<StippleSet> load_cached_stipples(const std::filesystem::path& dir, const Mesh& mesh,
                                               const GenerationParams& params) {
    const uint64_t key = stipple_cache_key(mesh, params);
    std::ifstream in(entry_path(dir, key), std::ios::binary);
    if (!in) return std::nullopt;
    Header header{};
    if (!in.read(reinterpret_cast<char*>(&header), sizeof(header))) return std::nullopt;
    const size_t triangles = mesh.triangle_count();
    if (header.magic != kMagic || header.version != kVersion || header.key != key || header.triangles != triangles ||
        header.stipples > (uint64_t(1) << 32))
        return std::nullopt;
    // Sizes are checked against the file before anything is allocated: a damaged entry is just a miss.
    std::error_code ec;
    const uintmax_t size = std::filesystem::file_size(entry_path(dir, key), ec);
    const uintmax_t expected =
        sizeof(Header) + header.stipples * (sizeof(glm::vec3) + 4) + (triangles + 1) * 4 + triangles * 4;
    if (ec || size != expected) return std::nullopt;
    StippleSet set;
    set.positions.resize(header.stipples);
    set.triangle.resize(header.stipples);
    set.first.resize(triangles + 1);
    set.selection.resize(triangles);
    in.read(reinterpret_cast<char*>(set.positions.data()), std::streamsize(set.positions.size() * sizeof(glm::vec3)));
    in.read(reinterpret_cast<char*>(set.triangle.data()), std::streamsize(set.triangle.size() * 4));
    in.read(reinterpret_cast<char*>(set.first.data()), std::streamsize(set.first.size() * 4));
    in.read(reinterpret_cast<char*>(set.selection.data()), std::streamsize(set.selection.size() * 4));
    if (!in) return std::nullopt;
    for (float value : set.selection)
        if (!(value >= 0.0f && value < 1.0f)) return std::nullopt;
    // Consistency, so a corrupted entry can never reach the GPU.
    if (set.first.front() != 0 || set.first.back() != header.stipples) return std::nullopt;
    for (size_t t = 0; t < triangles; ++t) {
        if (set.first[t] > set.first[t + 1]) return std::nullopt;
        for (uint32_t s = set.first[t]; s < set.first[t + 1]; ++s)
            if (set.triangle[s] != t) return std::nullopt;
    }
    set.density_per_area = header.density_per_area;
    set.poisson_radius = header.poisson_radius;
    return set;
}

void store_cached_stipples(const std::filesystem::path& dir, const Mesh& mesh, const GenerationParams& params,
                           const StippleSet& stipples) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) return;
    const uint64_t key = stipple_cache_key(mesh, params);
    const std::filesystem::path final_path = entry_path(dir, key);
    std::filesystem::path temporary = final_path;
    temporary += ".tmp" + std::to_string(std::chrono::steady_clock::now().time_since_epoch().count());
    {
        std::ofstream out(temporary, std::ios::binary);
        Header header{kMagic, kVersion, uint32_t(mesh.triangle_count()), key, stipples.size(),
                      stipples.density_per_area, stipples.poisson_radius};
        out.write(reinterpret_cast<const char*>(&header), sizeof(header));
        out.write(reinterpret_cast<const char*>(stipples.positions.data()),
                  std::streamsize(stipples.positions.size() * sizeof(glm::vec3)));
        out.write(reinterpret_cast<const char*>(stipples.triangle.data()), std::streamsize(stipples.triangle.size() * 4));
        out.write(reinterpret_cast<const char*>(stipples.first.data()), std::streamsize(stipples.first.size() * 4));
        out.write(reinterpret_cast<const char*>(stipples.selection.data()),
                  std::streamsize(stipples.selection.size() * 4));
        if (!out || stipples.selection.size() != mesh.triangle_count()) {
            out.close();
            std::filesystem::remove(temporary, ec);
            return;
        }
    }
    std::filesystem::rename(temporary, final_path, ec);
    if (ec) std::filesystem::remove(temporary, ec);
}

StippleSet generate_stipples_cached(const Mesh& mesh, const GenerationParams& params,
                                    const std::filesystem::path& dir) {
    const char* off = std::getenv("STIPPLE_NO_CACHE");
    if (off && std::strcmp(off, "0") != 0) return generate_stipples(mesh, params);
    auto start = std::chrono::steady_clock::now();
    if (std::optional<StippleSet> cached = load_cached_stipples(dir, mesh, params)) {
        cached->generation_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        cached->from_cache = true;
        return std::move(*cached);
    }
    StippleSet set = generate_stipples(mesh, params);
    set.selection = polygon_selection_values(mesh, params.seed);
    store_cached_stipples(dir, mesh, params, set);
    return set;
}

}  // namespace stipple
