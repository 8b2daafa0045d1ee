// The stipple cache: a reopened model with the same parameters gets the very same candidates back;
// anything else (other parameters, another mesh) is another entry; a damaged entry is detected, reported
// and regenerated; the folder stays under its size limit, least recently used first; a writer killed
// mid-entry leaves nothing that loads.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "core/decimal.hpp"
#include "core/error.hpp"
#include "mesh/primitives.hpp"
#include "core/hash.hpp"
#include "stipple/cache_entry_format.hpp"
#include "stipple/selection_order.hpp"
#include "stipple/stipple_cache.hpp"
#include "support/run_command.hpp"
#include "support/test_paths.hpp"
#include "support/test_shapes.hpp"

namespace stipple {
namespace {

namespace fs = std::filesystem;

bool same(const StippleSet& a, const StippleSet& b) {
    return a.positions == b.positions && a.triangle == b.triangle && a.first == b.first && a.selection == b.selection &&
           a.density_per_area == b.density_per_area;
}

fs::path entry_of(const fs::path& dir, const Mesh& mesh, const GenerationParams& params) {
    char name[40];
    std::snprintf(name, sizeof(name), "%016llx.stipples", static_cast<unsigned long long>(stipple_cache_key(mesh, params)));
    return dir / name;
}

uint64_t folder_bytes(const fs::path& dir) {
    uint64_t total = 0;
    for (const fs::directory_entry& file : fs::directory_iterator(dir)) total += file.file_size();
    return total;
}

void flip_byte(const fs::path& path, std::streamoff at) {
    std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
    f.seekg(at);
    char c = 0;
    f.read(&c, 1);
    c = char(c ^ 0x5A);
    f.seekp(at);
    f.write(&c, 1);
}

// Sizes read alike wherever they are given (--cache-size, STIPPLE_MAX_STORAGE_BUFFER, STIPPLE_GPU_MEMORY_LIMIT):
// the environment's own reader refused "64K" where --cache-size took it (until 2026-12-05).
TEST(StippleCache, SizesReadAlikeWithEitherCaseOfUnit) {
    EXPECT_EQ(parse_byte_size("64k"), 65536u);
    EXPECT_EQ(parse_byte_size("64K"), 65536u);
    EXPECT_EQ(parse_byte_size("1.5M"), 1572864u);
    EXPECT_EQ(parse_byte_size("2g"), 2147483648u);
    EXPECT_EQ(parse_byte_size("123456"), 123456u);
    for (const char* bad : {"", "K", "64KB", "-1k", "0x10", "1e30", " 64k"})
        EXPECT_FALSE(parse_byte_size(bad).has_value()) << "'" << bad << "'";
    EXPECT_EQ(parse_byte_size("--cache-size", "64K"), 65536u);
    EXPECT_THROW(parse_byte_size("--cache-size", "64KB"), Error);
    // The environment, read through the same rule: a device limited to 1024K is 1.0 MiB.
    const auto cache = test::temp_dir("cache-size-units");
    test::ScopedEnv limit("STIPPLE_MAX_STORAGE_BUFFER", "1024K");
    const test::CommandResult r = test::run_stipple({"render", test::source_path("assets/blobby.glb"), "--seed", "424245", "-o",
                                                     (cache / "never.png").string(), "--cache-dir", cache.string()});
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find("this device's largest is 1.0 MiB"), std::string::npos) << r.err;
}

// Where the cache lives: an empty STIPPLE_CACHE_DIR or XDG_CACHE_HOME, or a relative XDG_CACHE_HOME (invalid
// by the XDG specification), counts as unset; each made a cache folder in the current directory.
TEST(StippleCache, EmptyOrRelativeFolderVariablesAreUnset) {
    struct Saved {
        const char* name;
        std::optional<std::string> value;
    };
    std::vector<Saved> saved;
    for (const char* name : {"STIPPLE_CACHE_DIR", "XDG_CACHE_HOME", "HOME", "TMPDIR"}) {
        const char* v = std::getenv(name);
        saved.push_back({name, v ? std::optional<std::string>(v) : std::nullopt});
    }
    auto set = [](const char* name, const char* value) { ::setenv(name, value, 1); };
    set("HOME", "/home/someone");
    set("STIPPLE_CACHE_DIR", "");
    set("XDG_CACHE_HOME", "");
    EXPECT_EQ(default_stipple_cache_dir(), std::filesystem::path("/home/someone/.cache/stipple/stipples"));
    set("XDG_CACHE_HOME", "relative/cache");
    EXPECT_EQ(default_stipple_cache_dir(), std::filesystem::path("/home/someone/.cache/stipple/stipples"));
    set("XDG_CACHE_HOME", "/var/cache/me");
    EXPECT_EQ(default_stipple_cache_dir(), std::filesystem::path("/var/cache/me/stipple/stipples"));
    set("STIPPLE_CACHE_DIR", "/data/stipple");
    EXPECT_EQ(default_stipple_cache_dir(), std::filesystem::path("/data/stipple/stipples"));
    // Without a home (or with a relative one), the temporary folder's, per user; /tmp where TMPDIR names
    // nothing (temp_directory_path threw, and every command failed, even one given --cache-dir).
    const std::string per_user = "stipple-cache-" + std::to_string(getuid());
    set("STIPPLE_CACHE_DIR", "");
    set("XDG_CACHE_HOME", "");
    set("HOME", "relative/home");
    set("TMPDIR", "/nonexistent/tmp");
    EXPECT_EQ(default_stipple_cache_dir(), std::filesystem::path("/tmp") / per_user / "stipples");
    ::unsetenv("HOME");
    const std::filesystem::path tmp = test::temp_dir("cache_default_tmpdir");
    set("TMPDIR", tmp.c_str());
    EXPECT_EQ(default_stipple_cache_dir(), tmp / per_user / "stipples");
    EXPECT_EQ(std::filesystem::status(tmp / per_user).permissions() & std::filesystem::perms::all, std::filesystem::perms::owner_all)
        << "private: the entries' headers name the models";
    // One of that name that another user made first (only root can make it so here) is not used: a fresh
    // private folder of its own, said once.
    if (getuid() == 0) {
        ASSERT_EQ(::chown((tmp / per_user).c_str(), 65534, 65534), 0);
        testing::internal::CaptureStderr();
        const std::filesystem::path fresh = default_stipple_cache_dir();
        const std::string warning = testing::internal::GetCapturedStderr();
        EXPECT_NE(fresh, tmp / per_user / "stipples");
        EXPECT_EQ(fresh.parent_path().parent_path(), tmp);
        EXPECT_EQ(fresh.parent_path().filename().string().rfind(per_user + "-", 0), 0u) << fresh;
        EXPECT_NE(warning.find("is not this user's own private folder"), std::string::npos) << warning;
    }
    for (const Saved& s : saved) {
        if (s.value) ::setenv(s.name, s.value->c_str(), 1);
        else ::unsetenv(s.name);
    }
}

TEST(StippleCache, ReopeningReadsTheSameStipplesBack) {
    const auto dir = test::temp_dir("stipple_cache_roundtrip");
    const Mesh mesh = make_icosphere(4);
    GenerationParams params;
    params.dmax = 0.02f;
    const StippleSet generated = generate_stipples_cached(mesh, params, dir);
    EXPECT_FALSE(generated.from_cache);
    const StippleSet reopened = generate_stipples_cached(mesh, params, dir);
    EXPECT_TRUE(reopened.from_cache);
    EXPECT_TRUE(same(generated, reopened)) << "a hit must give the stipples a miss gave";
    // The polygons' selection values (§2.3) come back too, on their 16-bit steps: ranked by the stipples
    // the polygons draw when selected.
    const std::vector<float> ranked = polygon_selection_values(mesh, reopened, params.seed);
    ASSERT_EQ(reopened.selection.size(), ranked.size());
    for (size_t t = 0; t < ranked.size(); ++t) ASSERT_EQ(selection_step(reopened.selection[t]), selection_step(ranked[t]));
    const uint64_t bytes = fs::file_size(entry_of(dir, mesh, params));
    std::printf("%zu stipples on %zu polygons: generated in %.3f s, read back in %.4f s; %.2f bytes per stipple on disk\n",
                generated.size(), mesh.triangle_count(), generated.generation_seconds, reopened.generation_seconds,
                double(bytes) / double(generated.size()));
    EXPECT_LE(double(bytes) / double(generated.size()), 9.0);

    GenerationParams other = params;
    other.seed = 2;
    EXPECT_FALSE(load_cached_stipples(dir, mesh, other).has_value()) << "another seed is another entry";
    Mesh moved = mesh;
    moved.positions[0].x += 1e-3f;
    EXPECT_FALSE(load_cached_stipples(dir, moved, params).has_value()) << "another mesh is another entry";
}

TEST(StippleCache, DamagedEntriesAreReportedAndRegenerated) {
    const auto dir = test::temp_dir("stipple_cache_damaged");
    const Mesh mesh = make_icosphere(3);
    GenerationParams params;
    params.dmax = 0.02f;
    const StippleSet generated = generate_stipples_cached(mesh, params, dir);
    const fs::path entry = entry_of(dir, mesh, params);
    ASSERT_TRUE(fs::exists(entry));
    const uint64_t size = fs::file_size(entry);
    const std::vector<char> good = [&] {
        std::ifstream in(entry, std::ios::binary);
        return std::vector<char>((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    }();
    auto restore = [&] {
        std::ofstream out(entry, std::ios::binary | std::ios::trunc);
        out.write(good.data(), std::streamsize(good.size()));
    };
    struct Damage {
        const char* what;
        std::function<void()> apply;
    };
    const Damage damages[] = {
        {"a flipped byte in the compressed stipples", [&] { flip_byte(entry, std::streamoff(size - size / 3)); }},
        {"a flipped byte in the header", [&] { flip_byte(entry, 20); }},
        {"a flipped byte in the magic", [&] { flip_byte(entry, 0); }},
        {"a flipped byte in the version", [&] { flip_byte(entry, 8); }},
        {"a truncated entry", [&] { fs::resize_file(entry, size - 7); }},
        {"a truncated header", [&] { fs::resize_file(entry, 100); }},
        // A consistent header (sizes agreeing, hash recomputed) claiming 2^32 stipples over the same few
        // compressed bytes: refused before 16 GiB is allocated for them.
        {"a header claiming far more stipples than its bytes hold", [&] {
             cache_format::Header header{};
             std::memcpy(&header, good.data(), sizeof(header));
             header.stipples = uint64_t(1) << 32;
             header.raw_bytes = header.triangles * 6 + header.stipples * 4;
             header.header_hash = cache_format::hash_header(header);
             std::fstream f(entry, std::ios::in | std::ios::out | std::ios::binary);
             f.write(reinterpret_cast<const char*>(&header), sizeof(header));
         }},
        // Last: restore() would wait on it. Opened, a FIFO would wait for a writer forever.
        {"a FIFO in its place (not a regular file)", [&] {
             fs::remove(entry);
             ASSERT_EQ(mkfifo(entry.c_str(), 0600), 0);
         }},
    };
    for (const Damage& damage : damages) {
        SCOPED_TRACE(damage.what);
        restore();
        damage.apply();
        testing::internal::CaptureStderr();
        EXPECT_FALSE(load_cached_stipples(dir, mesh, params).has_value());
        const std::string warning = testing::internal::GetCapturedStderr();
        EXPECT_NE(warning.find("warning: " + entry.string() + ": damaged stipple cache entry"), std::string::npos) << warning;
        EXPECT_EQ(std::count(warning.begin(), warning.end(), '\n'), 1) << "one line: " << warning;
        // Regenerated over the damaged entry, and good again.
        testing::internal::CaptureStderr();
        const StippleSet again = generate_stipples_cached(mesh, params, dir);
        testing::internal::GetCapturedStderr();
        EXPECT_FALSE(again.from_cache);
        EXPECT_TRUE(same(again, generated));
        EXPECT_TRUE(load_cached_stipples(dir, mesh, params).has_value());
    }
}

// A folder in an entry's place: reported as damaged when read, and the new entry that cannot replace it is
// said (it was silently never kept, and every run generated again with only the first warning).
TEST(StippleCache, AFolderInAnEntrysPlaceIsSaid) {
    const auto dir = test::temp_dir("stipple_cache_folder_in_place");
    const Mesh mesh = make_icosphere(2);
    GenerationParams params;
    params.dmax = 0.02f;
    const StippleSet generated = generate_stipples_cached(mesh, params, dir);
    const fs::path entry = entry_of(dir, mesh, params);
    fs::remove(entry);
    fs::create_directories(entry / "inside");
    testing::internal::CaptureStderr();
    const StippleSet again = generate_stipples_cached(mesh, params, dir);
    const std::string warning = testing::internal::GetCapturedStderr();
    EXPECT_TRUE(same(again, generated));
    EXPECT_NE(warning.find("warning: " + entry.string() + ": cannot put the new stipple cache entry in place"), std::string::npos)
        << warning;
    EXPECT_TRUE(fs::is_directory(entry / "inside")) << "not ours to remove";
    for (const fs::directory_entry& file : fs::directory_iterator(dir))
        EXPECT_EQ(file.path().filename().string().find(".tmp"), std::string::npos) << file.path();
}

// A cache folder that cannot be made is said once, and the stipples are still drawn.
TEST(StippleCache, AFolderThatCannotBeMadeIsSaidOnce) {
    const auto dir = test::temp_dir("stipple_cache_unusable");
    std::ofstream(dir / "a_file") << "not a folder";
    const fs::path unusable = dir / "a_file" / "cache";
    const Mesh mesh = make_icosphere(2);
    GenerationParams params;
    params.dmax = 0.02f;
    testing::internal::CaptureStderr();
    const StippleSet first = generate_stipples_cached(mesh, params, unusable);
    params.seed = 2;
    const StippleSet second = generate_stipples_cached(mesh, params, unusable);
    const std::string warning = testing::internal::GetCapturedStderr();
    EXPECT_GT(first.size(), 0u);
    EXPECT_GT(second.size(), 0u);
    EXPECT_NE(warning.find("warning: " + unusable.string() + ": cannot keep the stipple cache there"), std::string::npos)
        << warning;
    EXPECT_EQ(std::count(warning.begin(), warning.end(), '\n'), 1) << "once: " << warning;
}

TEST(StippleCache, TheFolderStaysUnderItsLimitLeastRecentlyUsedFirst) {
    const auto dir = test::temp_dir("stipple_cache_limit");
    const Mesh mesh = make_icosphere(2);
    GenerationParams params;
    params.dmax = 0.005f;
    const uint64_t one_entry = [&] {
        generate_stipples_cached(mesh, params, dir);
        return fs::file_size(entry_of(dir, mesh, params));
    }();
    const uint64_t limit = 3 * one_entry + one_entry / 2;  // room for three entries
    const GenerationParams first = params;
    for (uint64_t seed = 2; seed <= 12; ++seed) {
        params.seed = seed;
        const StippleSet set = generate_stipples(mesh, params);
        StippleSet finished = set;
        finish_generated_stipples(mesh, seed, finished);
        store_cached_stipples(dir, mesh, params, finished, limit);
        EXPECT_LE(folder_bytes(dir), limit) << "after entry " << seed;
        EXPECT_TRUE(fs::exists(entry_of(dir, mesh, params))) << "the entry just written is never evicted";
        // Reading the first entry makes it the most recently used, so it survives the evictions.
        if (seed <= 6) {
            fs::last_write_time(entry_of(dir, mesh, first), fs::file_time_type::clock::now() + std::chrono::seconds(seed));
        }
    }
    EXPECT_EQ(list_cache_entries(dir).size(), 3u);
    EXPECT_FALSE(fs::exists(entry_of(dir, mesh, [&] { GenerationParams p = params; p.seed = 3; return p; }())))
        << "an old entry nobody read should have been evicted";
    // An entry larger than the whole limit is not kept, and evicts nothing (it emptied the folder of every other
    // entry and still stood beyond the limit).
    {
        GenerationParams dense = params;
        dense.dmax = 0.05f;
        StippleSet finished = generate_stipples(mesh, dense);
        finish_generated_stipples(mesh, dense.seed, finished);
        store_cached_stipples(dir, mesh, dense, finished, limit);
        EXPECT_FALSE(fs::exists(entry_of(dir, mesh, dense)));
        EXPECT_EQ(list_cache_entries(dir).size(), 3u);
    }
    // Files the cache did not write, even with its extension, are neither listed nor removed (a folder
    // shared with a user's own files: "cache --clear" removed their "notes.stipples" until 2026-12-07).
    const std::vector<std::string> foreign = {"notes.stipples", "0123456789ABCDEF.stipples", "0123456789abcdef.stipples.bak",
                                              "notes.stipples.tmp42-7", "0123456789abcde.stipples"};
    for (const std::string& name : foreign) std::ofstream(dir / name) << std::string(size_t(limit), 'x');
    params.seed = 13;
    {
        StippleSet finished = generate_stipples(mesh, params);
        finish_generated_stipples(mesh, params.seed, finished);
        store_cached_stipples(dir, mesh, params, finished, limit);
    }
    EXPECT_EQ(list_cache_entries(dir).size(), 3u) << "foreign files are not entries";
    EXPECT_GT(clear_cache(dir), 0u);
    EXPECT_TRUE(list_cache_entries(dir).empty());
    for (const std::string& name : foreign) EXPECT_TRUE(fs::exists(dir / name)) << name << " is not the cache's";
    // A folder not made yet is an empty cache; one that cannot be read is said (a path under a file
    // listed as an empty cache, and clearing it "freed 0 MB", both with exit status 0).
    EXPECT_TRUE(list_cache_entries(dir / "not-made-yet").empty());
    const fs::path under_a_file = dir / "plain-file" / "stipples";
    std::ofstream(dir / "plain-file") << "x";
    for (int clear = 0; clear < 2; ++clear) {
        try {
            if (clear) clear_cache(under_a_file);
            else list_cache_entries(under_a_file);
            ADD_FAILURE() << "a folder under a file was read as an empty cache";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("cannot read the stipple cache folder"), std::string::npos) << e.what();
        }
    }
}

TEST(StippleCache, AWriterKilledMidEntryLeavesNothingThatLoads) {
    const auto dir = test::temp_dir("stipple_cache_killed");
    const fs::path cache = dir / "cache";
    const std::string model = (dir / "sphere.obj").string();
    {
        const Mesh sphere = make_icosphere(3);
        std::ofstream out(model);
        for (const glm::vec3& p : sphere.positions) out << "v " << p.x << " " << p.y << " " << p.z << "\n";
        for (size_t t = 0; t < sphere.triangle_count(); ++t)
            out << "f " << sphere.indices[3 * t] + 1 << " " << sphere.indices[3 * t + 1] + 1 << " "
                << sphere.indices[3 * t + 2] + 1 << "\n";
    }
    const std::vector<std::string> info = {"info", model, "--dmax", "0.02", "--cache-dir", cache.string()};
    const test::CommandResult killed = [&] {
        test::ScopedEnv crash("STIPPLE_CACHE_CRASH_AFTER_BYTES", "300");  // dies inside the entry's data, as a kill would
        return test::run_stipple(info);
    }();
    EXPECT_EQ(killed.exit_code, 137);
    size_t temporaries = 0;
    for (const fs::directory_entry& file : fs::directory_iterator(cache)) temporaries += file.path().extension() != ".stipples";
    EXPECT_EQ(temporaries, 1u) << "the killed writer's half file stays a temporary file";
    EXPECT_TRUE(list_cache_entries(cache).empty()) << "no entry may exist: it would load half an entry";

    const test::CommandResult again = test::run_stipple(info);
    ASSERT_EQ(again.exit_code, 0) << again.err;
    EXPECT_EQ(again.err, "") << "a half-written temporary file is never read";
    EXPECT_NE(again.out.find("generation time"), std::string::npos);
    const test::CommandResult reopened = test::run_stipple(info);
    EXPECT_NE(reopened.out.find("read from the stipple cache"), std::string::npos) << reopened.out;
}

// A cache entry holds what generation made, keyed by the parameters, not by the code: a change to
// generation that moves stipples, or to the selection values kept beside them, must come with a new
// kVersion, or users keep loading what the new code would not make (and tests compare against it).
// This fingerprint of both fails the moment either changes; update kGenerationFingerprint and kVersion
// together.
TEST(StippleCache, GenerationChangesComeWithANewCacheVersion) {
    uint64_t fingerprint = 0;
    GenerationParams params;
    // Small triangles; two large ones; long slivers cut in pieces (make_grid(1)'s are not, at this density);
    // slivers dense enough for slabs along them, which leave them whole, laid along an axis and along none
    // (cache format 15); boxes not turned, whose selection values are made uniform per facing (16); a fine
    // sphere at a low density, most of whose triangles hold no candidate and are ranked after all others (17);
    // a sphere of small triangles and the slivers again with the coarse class (19).
    Mesh tilted = make_cad_cylinder(256);
    const glm::mat3 turn = glm::mat3(glm::rotate(glm::mat4(1.0f), 0.7f, glm::normalize(glm::vec3(1.0f, 0.0f, 0.6f))));
    for (glm::vec3& p : tilted.positions) p = turn * p;
    for (glm::vec3& n : tilted.normals) n = turn * n;
    struct Case {
        Mesh mesh;
        float dmax;
        uint64_t max_stipples = GenerationParams{}.max_stipples;
        bool coarse_class = false;
    };
    const Case meshes[] = {{make_icosphere(2), 0.01f},
                           {make_grid(1), 0.01f},
                           {make_cad_cylinder(48), 0.01f},
                           {make_cad_cylinder(256), 0.05f},
                           {tilted, 0.05f},
                           {test::make_box_cloud(2000, 0.02f), 0.25f, 4 * 12 * 2000},
                           {make_icosphere(5), 0.001f},
                           {make_icosphere(4), 0.02f, GenerationParams{}.max_stipples, true},
                           {make_cad_cylinder(256), 0.002f, GenerationParams{}.max_stipples, true}};
    for (const auto& [mesh, dmax, max_stipples, coarse_class] : meshes) {
        // Without the class, generation has made the same stipples since cache format 18.
        if (coarse_class && !params.coarse_class) {
            EXPECT_EQ(fingerprint, 0x70fb05d5c2ee5abcull) << "generation without the coarse class changed";
        }
        params.dmax = dmax;
        params.max_stipples = max_stipples;
        params.coarse_class = coarse_class;
        const StippleSet set = generate_stipples(mesh, params);
        ASSERT_GT(set.size(), 1000u);
        for (const glm::vec3& p : set.positions) {
            uint32_t bits[3];
            std::memcpy(bits, &p, sizeof(bits));
            fingerprint = mix64(fingerprint ^ (uint64_t(bits[0]) << 32 | bits[1]) ^ mix64(bits[2]));
        }
        for (const float value : polygon_selection_values(mesh, set, params.seed)) {
            uint32_t bits;
            std::memcpy(&bits, &value, sizeof(bits));
            fingerprint = mix64(fingerprint ^ bits);
        }
    }
    char text[32];
    std::snprintf(text, sizeof(text), "0x%016llx", static_cast<unsigned long long>(fingerprint));
    EXPECT_EQ(fingerprint, cache_format::kGenerationFingerprint)
        << "generation makes other stipples or selection values than cache format " << cache_format::kVersion
        << " recorded: bump kVersion in src/stipple/cache_entry_format.hpp and set kGenerationFingerprint = " << text;
}

}  // namespace
}  // namespace stipple
