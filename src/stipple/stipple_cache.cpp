#include "stipple/stipple_cache.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

#include <zstd.h>

#include "core/decimal.hpp"
#include "core/error.hpp"
#include "core/hash.hpp"
#include "core/parallel.hpp"
#include "core/timing.hpp"
#include "params/param_table.hpp"
#include "stipple/barycentric.hpp"
#include "stipple/cache_entry_format.hpp"
#include "stipple/selection_order.hpp"

namespace stipple {

namespace {

using cache_format::Header;

// How many times zstd may shrink a real entry's stipple places at most (they shrink about 1x).
constexpr uint64_t kMostCompression = 16;

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
    char name[40];
    std::snprintf(name, sizeof(name), "%016llx%s", static_cast<unsigned long long>(key), cache_format::kExtension);
    return dir / name;
}

// Once per process: the stipples are still drawn, only generated again next time.
void warn_unusable_folder(const std::filesystem::path& dir, const std::string& reason) {
    static std::atomic<bool> warned{false};
    if (warned.exchange(true)) return;
    std::fprintf(stderr, "stipple: warning: %s: cannot keep the stipple cache there (%s); stipples are generated every time\n",
                 dir.c_str(), reason.c_str());
}

void warn_damaged(const std::filesystem::path& path, const char* problem) {
    std::fprintf(stderr, "stipple: warning: %s: damaged stipple cache entry (%s); generating the stipples again\n",
                 path.c_str(), problem);
}

template <class T>
void append(std::vector<unsigned char>& out, const T* data, size_t count) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(data);
    out.insert(out.end(), bytes, bytes + count * sizeof(T));
}

// Fault injection for the test that a killed writer leaves no entry: STIPPLE_CACHE_CRASH_AFTER_BYTES=N
// ends the process abruptly once N bytes of an entry are written, as a kill would.
void maybe_crash(uint64_t written) {
    static const char* limit = std::getenv("STIPPLE_CACHE_CRASH_AFTER_BYTES");
    if (limit && written >= std::strtoull(limit, nullptr, 10)) _exit(137);
}

}  // namespace

std::filesystem::path default_stipple_cache_dir() {
    // An empty variable is unset (it made a cache folder in whatever the current directory was), and so is
    // a relative XDG_CACHE_HOME (the XDG Base Directory specification: such a value is invalid).
    if (const char* dir = std::getenv("STIPPLE_CACHE_DIR"); dir && *dir) return std::filesystem::path(dir) / "stipples";
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && std::filesystem::path(xdg).is_absolute())
        return std::filesystem::path(xdg) / "stipple" / "stipples";
    // A relative HOME is no home (it put the cache wherever the current directory was).
    if (const char* home = std::getenv("HOME"); home && std::filesystem::path(home).is_absolute())
        return std::filesystem::path(home) / ".cache" / "stipple" / "stipples";
    // The temporary folder, per user (one shared name let the first user own it and others plant entries there),
    // and /tmp where TMPDIR names nothing usable (temp_directory_path threw, failing even runs that asked for
    // another cache folder or none).
    std::error_code error;
    std::filesystem::path tmp = std::filesystem::temp_directory_path(error);
    if (error || !tmp.is_absolute()) tmp = "/tmp";
    // Made private (0700), and used only while it is this user's own folder: another user could make one of
    // its name first, to read or plant entries. Otherwise a fresh private folder of its own, said once.
    const std::filesystem::path mine = tmp / ("stipple-cache-" + std::to_string(getuid()));
    mkdir(mine.c_str(), 0700);
    struct stat seen {};
    if (lstat(mine.c_str(), &seen) == 0 && S_ISDIR(seen.st_mode) && seen.st_uid == getuid() &&
        ((seen.st_mode & 077) == 0 || chmod(mine.c_str(), 0700) == 0))  // one made before it was private
        return mine / "stipples";
    std::string fresh = (tmp / ("stipple-cache-" + std::to_string(getuid()) + "-XXXXXX")).string();
    if (!mkdtemp(fresh.data())) return mine / "stipples";  // unusable: the cache says so when it writes
    static std::atomic<bool> warned{false};
    if (!warned.exchange(true))
        std::fprintf(stderr, "stipple: warning: %s is not this user's own private folder; the stipple cache is kept in %s\n",
                     mine.c_str(), fresh.c_str());
    return std::filesystem::path(fresh) / "stipples";
}

StippleCacheSettings& stipple_cache_settings() {
    static StippleCacheSettings settings = [] {
        StippleCacheSettings s;
        // Strict, as STIPPLE_VALIDATION: "no" or "false" read as set (anything but "0") hid a typo.
        if (const char* off = std::getenv("STIPPLE_NO_CACHE"); off && *off) {
            if (std::strcmp(off, "1") != 0 && std::strcmp(off, "0") != 0)
                fail(std::string("STIPPLE_NO_CACHE=") + off + " must be 1 (always generate) or 0 (use the cache)");
            s.enabled = std::strcmp(off, "0") == 0;
        }
        return s;
    }();
    return settings;
}

uint64_t parse_byte_size(const std::string& option, const std::string& text) {
    const std::optional<uint64_t> bytes = stipple::parse_byte_size(std::string_view(text));
    if (!bytes) fail(option + ": '" + text + "' is not a size (bytes, or a number with k, M or G)");
    return *bytes;
}

uint64_t stipple_cache_key(const Mesh& mesh, const GenerationParams& params, std::span<const float> headroom) {
    uint64_t h = mix64(cache_format::kMagic ^ cache_format::kVersion);
    h = hash_bytes(h, mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3));
    h = hash_bytes(h, mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t));
    // The parameters that shape generation, as the parameter table marks them, and the reference view.
    std::vector<double> values = generation_values(params);
    values.push_back(kReferenceHeight);
    h = hash_bytes(h, values.data(), values.size() * sizeof(double));
    // Only animated models hash their headroom, so a static model's key is what it always was.
    return headroom.empty() ? h : hash_bytes(mix64(h ^ 0x48454144524F4F4Dull), headroom.data(), headroom.size_bytes());
}

void finish_generated_stipples(const Mesh& mesh, uint64_t seed, StippleSet& stipples) {
    // Each stipple on its own: on both cores (0.13 s on one for the 8M-stipple dragon).
    parallel_for_chunks(stipples.size(), size_t(1) << 16, [&](size_t, size_t begin, size_t end) {
        for (size_t i = begin; i < end; ++i) {
            const uint32_t t = stipples.triangle[i];
            stipples.positions[i] = unpack_barycentric(mesh, t, pack_barycentric(mesh, t, stipples.positions[i]));
        }
    });
    stipples.selection = polygon_selection_values(mesh, stipples, seed);
    for (float& value : stipples.selection) value = selection_from_step(selection_step(value));
}

std::optional<StippleSet> load_cached_stipples(const std::filesystem::path& dir, const Mesh& mesh,
                                               const GenerationParams& params, std::span<const float> headroom) {
    const uint64_t key = stipple_cache_key(mesh, params, headroom);
    const std::filesystem::path path = entry_path(dir, key);
    // Only a regular file: opening a FIFO left there would wait for a writer forever.
    std::error_code kind_error;
    if (!std::filesystem::is_regular_file(path, kind_error)) {
        if (std::filesystem::exists(path, kind_error)) warn_damaged(path, "not a regular file");
        return std::nullopt;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    Header header{};
    const size_t triangles = mesh.triangle_count();
    if (!in.read(reinterpret_cast<char*>(&header), sizeof(header))) return warn_damaged(path, "truncated header"), std::nullopt;
    // The key mixes in the format's version, so an older format lies under another name: a foreign magic or
    // version here is damage (it was passed over silently until 2026-12-04).
    if (header.magic != cache_format::kMagic || header.version != cache_format::kVersion)
        return warn_damaged(path, "not an entry of this format"), std::nullopt;
    if (!cache_format::header_valid(header)) return warn_damaged(path, "header checksum"), std::nullopt;
    if (header.key != key || header.triangles != triangles) return std::nullopt;  // another mesh's (a 64-bit collision)
    const uint64_t raw_expected = header.triangles * 6 + header.stipples * 4;
    std::error_code ec;
    const uintmax_t size = std::filesystem::file_size(path, ec);
    // Sizes are checked against the file before anything is allocated.
    if (ec || header.raw_bytes != raw_expected || header.stipples > (uint64_t(1) << 32) ||
        size != sizeof(Header) + header.compressed_bytes)
        return warn_damaged(path, "sizes"), std::nullopt;
    // Each stipple's place is a pair of near-random 16-bit fractions, which zstd cannot shrink much (real
    // entries hold 4-5 bytes a stipple): an entry claiming many times more stipples than its compressed bytes
    // could hold is damaged or forged, and is refused before its claim is allocated (a 300-byte file with a
    // consistent header otherwise asked for 16 GiB).
    if (header.stipples * 4 > kMostCompression * header.compressed_bytes + 65536)
        return warn_damaged(path, "sizes"), std::nullopt;
    std::vector<char> compressed(header.compressed_bytes);
    if (!in.read(compressed.data(), std::streamsize(compressed.size()))) return warn_damaged(path, "truncated"), std::nullopt;
    if (ZSTD_getFrameContentSize(compressed.data(), compressed.size()) != header.raw_bytes)
        return warn_damaged(path, "sizes"), std::nullopt;
    std::vector<unsigned char> raw(header.raw_bytes);
    const size_t got = ZSTD_decompress(raw.data(), raw.size(), compressed.data(), compressed.size());
    if (ZSTD_isError(got) || got != raw.size()) return warn_damaged(path, "checksum"), std::nullopt;

    StippleSet set;
    set.first.assign(triangles + 1, 0);
    set.selection.resize(triangles);
    const unsigned char* counts = raw.data();
    const unsigned char* steps = counts + 4 * triangles;
    const unsigned char* uvs = steps + 2 * triangles;
    for (size_t t = 0; t < triangles; ++t) {
        uint32_t count = 0;
        uint16_t step = 0;
        std::memcpy(&count, counts + 4 * t, 4);
        std::memcpy(&step, steps + 2 * t, 2);
        if (uint64_t(set.first[t]) + count > header.stipples) return warn_damaged(path, "counts"), std::nullopt;
        set.first[t + 1] = set.first[t] + count;
        set.selection[t] = selection_from_step(step);
    }
    if (set.first.back() != header.stipples) return warn_damaged(path, "counts"), std::nullopt;
    set.positions.resize(header.stipples);
    set.triangle.resize(header.stipples);
    for (size_t t = 0; t < triangles; ++t)
        for (uint32_t s = set.first[t]; s < set.first[t + 1]; ++s) {
            uint32_t uv = 0;
            std::memcpy(&uv, uvs + 4 * size_t(s), 4);
            set.triangle[s] = uint32_t(t);
            set.positions[s] = unpack_barycentric(mesh, uint32_t(t), uv);
        }
    set.density_per_area = header.density_per_area;
    set.poisson_radius = header.poisson_radius;
    std::filesystem::last_write_time(path, std::filesystem::file_time_type::clock::now(), ec);  // its last use
    return set;
}

void store_cached_stipples(const std::filesystem::path& dir, const Mesh& mesh, const GenerationParams& params,
                           const StippleSet& stipples, uint64_t max_bytes, std::span<const float> headroom) {
    const size_t triangles = mesh.triangle_count();
    if (stipples.selection.size() != triangles || stipples.first.size() != triangles + 1) return;
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) return warn_unusable_folder(dir, ec.message());
    std::vector<unsigned char> raw;
    raw.reserve(triangles * 6 + stipples.size() * 4);
    for (size_t t = 0; t < triangles; ++t) {
        const uint32_t count = stipples.count(t);
        append(raw, &count, 1);
    }
    for (size_t t = 0; t < triangles; ++t) {
        const uint16_t step = selection_step(stipples.selection[t]);
        append(raw, &step, 1);
    }
    for (size_t i = 0; i < stipples.size(); ++i) {
        const uint32_t uv = pack_barycentric(mesh, stipples.triangle[i], stipples.positions[i]);
        append(raw, &uv, 1);
    }
    std::vector<char> compressed(ZSTD_compressBound(raw.size()));
    ZSTD_CCtx* context = ZSTD_createCCtx();
    if (!context) return;
    ZSTD_CCtx_setParameter(context, ZSTD_c_compressionLevel, 3);
    ZSTD_CCtx_setParameter(context, ZSTD_c_checksumFlag, 1);  // zstd verifies the data when it reads it back
    const size_t packed = ZSTD_compress2(context, compressed.data(), compressed.size(), raw.data(), raw.size());
    ZSTD_freeCCtx(context);
    if (ZSTD_isError(packed)) return;
    // An entry larger than the folder's whole limit is not kept: it emptied the folder of every other entry
    // and still stood beyond the limit (a 9.9 MiB entry under --cache-size 1M).
    if (packed + sizeof(Header) > max_bytes) return;

    Header header{};
    header.magic = cache_format::kMagic;
    header.version = cache_format::kVersion;
    header.header_bytes = sizeof(Header);
    header.key = stipple_cache_key(mesh, params, headroom);
    header.triangles = triangles;
    header.stipples = stipples.size();
    header.density_per_area = stipples.density_per_area;
    header.poisson_radius = stipples.poisson_radius;
    header.raw_bytes = raw.size();
    header.compressed_bytes = packed;
    std::strncpy(header.model, mesh.source.c_str(), sizeof(header.model) - 1);
    header.header_hash = cache_format::hash_header(header);

    const std::filesystem::path final_path = entry_path(dir, header.key);
    std::filesystem::path temporary = final_path;
    temporary += ".tmp" + std::to_string(getpid()) + "-" + std::to_string(Clock::now().time_since_epoch().count());
    {
        std::ofstream out(temporary, std::ios::binary);
        out.write(reinterpret_cast<const char*>(&header), sizeof(header));
        uint64_t written = sizeof(header);
        for (size_t at = 0; at < packed && out; at += 1 << 20) {
            const size_t chunk = std::min<size_t>(packed - at, 1 << 20);
            out.write(compressed.data() + at, std::streamsize(chunk));
            written += chunk;
            maybe_crash(written);
        }
        if (!out.flush()) {
            const std::string reason = errno != 0 ? std::strerror(errno) : "cannot write";
            out.close();
            std::filesystem::remove(temporary, ec);
            return warn_unusable_folder(dir, reason);
        }
    }
    std::filesystem::rename(temporary, final_path, ec);
    if (ec) {
        // Something not ours in the entry's place (a folder of its name): said, rather than the entry
        // silently never kept.
        std::fprintf(stderr, "stipple: warning: %s: cannot put the new stipple cache entry in place (%s)\n",
                     final_path.c_str(), ec.message().c_str());
        std::filesystem::remove(temporary, ec);
        return;
    }
    enforce_cache_limit(dir, max_bytes, final_path);
}

StippleSet generate_stipples_cached(const Mesh& mesh, const GenerationParams& params, std::span<const float> headroom) {
    const StippleCacheSettings& settings = stipple_cache_settings();
    if (!settings.enabled) {
        const auto start = Clock::now();
        StippleSet set = generate_stipples(mesh, params, headroom);
        finish_generated_stipples(mesh, params.seed, set);  // as a cache hit would return it
        // The ranking counts as preprocessing, as make_stipples and the bench count it (info printed
        // 0.26-0.80 s for a 3M-triangle plane that took 4.2 s to open).
        set.generation_seconds = seconds_since(start);
        return set;
    }
    return generate_stipples_cached(mesh, params, settings.dir, headroom);
}

StippleSet generate_stipples_cached(const Mesh& mesh, const GenerationParams& params,
                                    const std::filesystem::path& dir, std::span<const float> headroom) {
    const auto start = Clock::now();
    if (std::optional<StippleSet> cached = load_cached_stipples(dir, mesh, params, headroom)) {
        cached->generation_seconds = seconds_since(start);
        cached->from_cache = true;
        return std::move(*cached);
    }
    StippleSet set = generate_stipples(mesh, params, headroom);
    finish_generated_stipples(mesh, params.seed, set);
    set.generation_seconds = seconds_since(start);  // with the ranking, as above
    store_cached_stipples(dir, mesh, params, set, stipple_cache_settings().max_bytes, headroom);
    return set;
}

}  // namespace stipple
