// The stipple command as a user runs it: the default scene, figures from info, and one clear line
// with a non-zero exit for every kind of bad input (never a crash, a hang or a validation message).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <set>

#include <nlohmann/json.hpp>

#include "core/huge_pages.hpp"
#include "core/memory.hpp"
#include "io/png_io.hpp"
#include "stipple/object_data.hpp"
#include "support/image_checks.hpp"
#include "support/model_files.hpp"
#include "support/run_command.hpp"
#include "support/test_paths.hpp"

namespace stipple {
namespace {

using test::run_stipple;

size_t count_lines(const std::string& s) { return std::count(s.begin(), s.end(), '\n'); }

// A shell prefix for a command that should refuse its input before using much memory or time: a memory limit
// (ulimit -v, KiB) that catches it if it does not, and a timeout. Not the memory limit under a sanitizer, whose
// shadow memory reserves more address space than any such limit leaves (the binary would not start).
std::string guarded(const char* kilobytes, int seconds) {
    // Two threads: each thread's stack is address space too, and a machine of many cores would spend the limit on them.
    const std::string timeout = "STIPPLE_THREADS=2 timeout " + std::to_string(seconds);
    return kHugePageNew ? "ulimit -v " + std::string(kilobytes) + "; " + timeout : timeout;
}

// The count `render --stats` prints; -1 without one.
long drawn_stipples(const test::CommandResult& r) {
    const size_t at = r.out.find("drawn stipples:");
    return at == std::string::npos ? -1 : std::stol(r.out.substr(at + 15));
}

void write_file(const std::filesystem::path& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary);
    out << bytes;
}

TEST(CliRender, NoArgumentsRendersTheDefaultScene) {
    auto dir = test::temp_dir("cli-default");
    // The README's command is `stipple render` with no MODEL; -o only keeps the test's file apart.
    auto result = run_stipple({"render", "-o", (dir / "default.png").string(), "--mask", (dir / "mask.png").string()});
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_EQ(result.err.find("validation"), std::string::npos) << result.err;
    Image image = read_png((dir / "default.png").string());
    EXPECT_EQ(image.width, 1280);
    EXPECT_EQ(image.height, 1024);
    Image mask = read_png((dir / "mask.png").string());
    size_t covered = 0, inked = 0;
    for (size_t i = 0; i < size_t(image.width) * image.height; ++i) {
        bool inside = mask.pixels[i * mask.channels] > 127;
        covered += inside;
        inked += inside && image.pixels[i * image.channels] < 128;
    }
    EXPECT_GT(covered, 100000u) << "the default scene should fill a good part of the frame";
    EXPECT_GT(double(inked) / double(covered), 0.03);
}

// A write beyond the file-size limit (ulimit -f) is one line and exit 1, and the image that was there stays:
// the signal of that limit killed the process with no word (exit 153), leaving a truncated image in place
// of the good one.
TEST(CliRender, AnImageBeyondTheFileSizeLimitLeavesTheOneThatWasThere) {
    const auto dir = test::temp_dir("cli-file-size-limit");
    const std::string path = (dir / "frame.png").string(), cache = (dir / "cache").string();
    auto small = run_stipple({"render", "-o", path, "--width", "64", "--height", "48", "--cache-dir", cache});
    ASSERT_EQ(small.exit_code, 0) << small.err;
    std::ifstream before_in(path, std::ios::binary);
    const std::string before((std::istreambuf_iterator<char>(before_in)), std::istreambuf_iterator<char>());
    ASSERT_LT(before.size(), 16u * 1024u);
    auto large = run_stipple({"render", "-o", path, "--cache-dir", cache}, "ulimit -f 16;");  // 8 KiB in dash's 512-byte blocks, 16 KiB in bash's
    EXPECT_EQ(large.exit_code, 1) << large.err;
    EXPECT_NE(large.err.find(path + ": cannot write PNG: File too large"), std::string::npos) << large.err;
    std::ifstream after_in(path, std::ios::binary);
    EXPECT_EQ(std::string((std::istreambuf_iterator<char>(after_in)), std::istreambuf_iterator<char>()), before);
    for (const std::string& name : test::folder_entries(dir.string())) EXPECT_EQ(name.find(".part-"), std::string::npos) << name;
}

// The JSON parses whatever the file is called (a quote or backslash in its path was printed as it stood),
// and a cache read gives no generation speed (it gave the cache's reading speed, 83M stipples/s).
TEST(CliRender, InfoPrintsFiguresAsJson) {
    auto dir = test::temp_dir("cli-info");
    // And a byte that is not UTF-8 (a Latin-1 e-acute), which JSON cannot hold: it reads as U+FFFD.
    const std::string model = (dir / "qu\"a\\d\t\xe9.obj").string();
    write_file(model, "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
    for (int run = 0; run < 2; ++run) {  // the second may read the first's stipples from the cache
        auto result = run_stipple({"info", model, "--json", "--cache-dir", (dir / "cache").string()});
        ASSERT_EQ(result.exit_code, 0) << result.err;
        EXPECT_EQ(count_lines(result.out), 1u);
        const nlohmann::json info = nlohmann::json::parse(result.out);
        EXPECT_EQ(info["model"], (dir / "qu\"a\\d\t\xef\xbf\xbd.obj").string());
        EXPECT_EQ(info["triangles"], 2);
        EXPECT_TRUE(info.contains("stipple_candidates"));
        EXPECT_EQ(info["stipples_per_second"].is_null(), info["from_cache"].get<bool>()) << result.out;
        EXPECT_EQ(info["from_cache"].get<bool>(), run == 1) << "the cache folder is the test's own";
        EXPECT_EQ(info["winding"]["border_edges"], 4) << "a square: open all round";
    }
    const test::CommandResult text = run_stipple({"info", model, "--cache-dir", (dir / "cache").string()});
    EXPECT_NE(text.out.find("surface:             open (4 border edges)"), std::string::npos) << text.out;
    // The cache lists the entry; another seed is another entry of the same model, told apart by its key.
    const auto listed = [&] { return run_stipple({"cache", "--list", "--cache-dir", (dir / "cache").string()}).out; };
    EXPECT_NE(listed().find("\n1 entry, "), std::string::npos) << listed();
    ASSERT_EQ(run_stipple({"info", model, "--seed", "2", "--cache-dir", (dir / "cache").string()}).exit_code, 0);
    const std::string two = listed();
    EXPECT_NE(two.find("\n2 entries, "), std::string::npos) << two;
    std::set<std::string> keys;
    for (size_t at = two.find('[', two.find('\n')); at != std::string::npos; at = two.find('[', at + 1))  // after the heading
        keys.insert(two.substr(at, two.find(']', at) - at));
    EXPECT_EQ(keys.size(), 2u) << two;
}

// An OBJ of `quads` squares of side 2 stacked 1e-4 apart: a large area in a small model, whose planned
// stipples at a high D_max and budget exceed what a machine can generate.
std::string stacked_quads_obj(int quads) {
    std::string stack;
    for (int i = 0; i < quads; ++i) {
        const std::string z = std::to_string(i * 1e-4);
        for (const char* corner : {"-1 -1 ", "1 -1 ", "1 1 ", "-1 1 "}) stack += std::string("v ") + corner + z + "\n";
        stack += "f " + std::to_string(4 * i + 1) + " " + std::to_string(4 * i + 2) + " " + std::to_string(4 * i + 3) + " " +
                 std::to_string(4 * i + 4) + "\n";
    }
    return stack;
}

// info checks the stipples it plans against the machine's memory before generating them, as render and
// tone check them against the device's: 2000 stacked quads at --dmax 16 with a budget of 2e9 stipples grew
// past 7 GB. Under a limit on memory, so that a generation started fails the test, not the machine.
// The machine's memory is capped at 16 GiB (the command's and this test's), so that a machine large enough to
// generate the budget tests the refusal too.
TEST(CliRender, InfoRefusesStipplesBeyondMemoryBeforeGenerating) {
    test::ScopedEnv limit("STIPPLE_HOST_MEMORY_LIMIT", "16G");
    const uint64_t most = physical_memory_bytes() / kGenerationBytesPerStipple;
    ASSERT_LT(most, 2'000'000'000u);
    const std::string stack = stacked_quads_obj(2000);
    const auto model = test::temp_dir("cli-info-memory") / "stack.obj";
    write_file(model, stack);
    const test::CommandResult r = run_stipple({"info", model.string(), "--dmax", "16", "--max-stipples", "2000000000"},
                                              guarded("4000000", 60));
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_EQ(count_lines(r.err), 1u) << r.err;
    EXPECT_NE(r.err.find(model.string() + ": 2000000000 stipples planned, whose generation needs about 74.5 GiB"),
              std::string::npos) << r.err;
    EXPECT_NE(r.err.find("(at most " + std::to_string(most) + " stipples): lower --dmax or --max-stipples"), std::string::npos)
        << r.err;
}

// render and tone check the planned stipples against the host's memory too, not only the device's (the
// tighter limit on lavapipe, not on a GPU of large buffers), here made 512 MiB with STIPPLE_HOST_MEMORY_LIMIT:
// 15M stipples would need about 572 MiB to generate, and the device holds them (lavapipe's 128-MiB buffers
// hold 16.7M). A value that is no size is refused, so that a typo does not silently test nothing.
TEST(CliRender, RenderAndToneRefuseStipplesBeyondTheHostsMemory) {
    const std::string stack = stacked_quads_obj(2000);
    const auto dir = test::temp_dir("cli-host-memory");
    const auto model = dir / "stack.obj";
    write_file(model, stack);
    test::ScopedEnv no_cache("STIPPLE_NO_CACHE", "1");
    const std::vector<std::string> budget = {"--dmax", "16", "--max-stipples", "15000000"};
    for (const std::string command : {"render", "tone"}) {
        std::vector<std::string> args = {command, model.string()};
        args.insert(args.end(), budget.begin(), budget.end());
        if (command == "render") args.insert(args.end(), {"-o", (dir / "never.png").string(), "--width", "64", "--height", "64"});
        const test::CommandResult r = [&] {
            test::ScopedEnv limit("STIPPLE_HOST_MEMORY_LIMIT", "512M");
            return run_stipple(args, guarded("8000000", 120));
        }();
        EXPECT_EQ(r.exit_code, 1) << command << ": " << r.err;
        // One line, beside render's note that the budget caps D_max 16.
        const size_t notes = r.err.find("stipple: note: " + model.string() + ": D_max 16 is capped") != std::string::npos;
        EXPECT_EQ(count_lines(r.err), 1u + notes) << command << ": " << r.err;
        EXPECT_NE(r.err.find(model.string() + ": 15000000 stipples planned, whose generation needs about 572.2 MiB"),
                  std::string::npos) << command << ": " << r.err;
        EXPECT_NE(r.err.find("more than this machine's 512.0 MiB of memory holds (at most 13421772 stipples)"), std::string::npos)
            << command << ": " << r.err;
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "never.png"));
    test::ScopedEnv typo("STIPPLE_HOST_MEMORY_LIMIT", "1 GB");
    const test::CommandResult r = run_stipple({"info", model.string()}, guarded("4000000", 60));
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_EQ(count_lines(r.err), 1u) << r.err;
    EXPECT_NE(r.err.find("STIPPLE_HOST_MEMORY_LIMIT=1 GB is not a size such as 2G"), std::string::npos) << r.err;
}

struct BadInput {
    const char* name;
    const char* file;      // written into a temp dir ("" = not written)
    const char* contents;  // nullptr: create a directory instead
    const char* expect;    // phrase expected in the message
};

// A failing case is named by its name, not printed as "32-byte object <...>".
void PrintTo(const BadInput& bad, std::ostream* out) { *out << bad.name; }

class CliBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(CliBadInput, OneLineNamingTheFileAndNonZeroExit) {
    const BadInput& bad = GetParam();
    auto dir = test::temp_dir(std::string("cli-bad-") + bad.name);
    auto path = dir / bad.file;
    if (!bad.contents)
        std::filesystem::create_directories(path);
    else if (std::string(bad.name) != "missing")
        write_file(path, std::string(bad.contents, std::strlen(bad.contents)));
    for (const char* command : {"render", "info"}) {
        std::vector<std::string> args{command, path.string()};
        if (std::string(command) == "render") args.insert(args.end(), {"-o", (dir / "out.png").string()});
        auto result = run_stipple(args);
        EXPECT_EQ(result.exit_code, 1) << command << ": " << result.err;
        EXPECT_EQ(count_lines(result.err), 1u) << result.err;
        EXPECT_NE(result.err.find(path.string()), std::string::npos) << result.err;
        EXPECT_NE(result.err.find(bad.expect), std::string::npos) << result.err;
        EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
    }
}

INSTANTIATE_TEST_SUITE_P(
    Files, CliBadInput,
    ::testing::Values(BadInput{"missing", "nothing.obj", "", "no such file"},
                      BadInput{"empty", "empty.ply", "", "empty"},
                      BadInput{"directory", "folder.obj", nullptr, "directory"},
                      BadInput{"garbage_ply", "garbage.ply", "\x13\x37\xff\x00garbage", "ply"},
                      BadInput{"truncated_ply", "short.ply",
                               "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                               "property float y\nproperty float z\nelement face 1\n"
                               "property list uchar int vertex_indices\nend_header\n\x01\x02",
                               "truncated"},
                      BadInput{"nan_obj", "nan.obj", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "NaN"},
                      BadInput{"index_out_of_range", "range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", "vertex"},
                      BadInput{"huge_count", "huge.ply",
                               "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000000\n"
                               "property float x\nproperty float y\nproperty float z\nend_header\n",
                               "1000000000000"},
                      BadInput{"unknown_extension", "model.xyz", "hello", "extension"},
                      BadInput{"zero_area", "line.obj", "v 0 0 0\nv 1 1 1\nv 2 2 2\nf 1 2 3\nf 3 2 1\n",
                               "no triangle with non-zero area"},
                      BadInput{"gltf_wrong_type", "types.gltf",
                               R"({"asset":{"version":"2.0"},"accessors":[{"componentType":5126,"count":-1,"type":"VEC3"}]})",
                               "accessors[0].count: expected a non-negative integer, got -1"},
                      BadInput{"gltf_misspelt_extension", "ext.gltf",
                               R"({"asset":{"version":"2.0"},"extensionsUsed":["KHR_materials_unlitt"]})",
                               "did you mean 'KHR_materials_unlit'?"},
                      BadInput{"gltf_1", "old.gltf", R"({"asset":{"version":"1.0"},"meshes":{}})",
                               "glTF 1.0 is not supported (convert to glTF 2.0)"},
                      BadInput{"ply_2_31_vertices", "claims.ply",
                               "ply\nformat binary_little_endian 1.0\nelement vertex 2147483648\nproperty float x\n"
                               "property float y\nproperty float z\nend_header\nabcd",
                               "header claims 2147483648 vertices, more than the file can hold"}),
    [](const auto& info) { return std::string(info.param.name); });

// A FIFO or a link to /dev/zero given as a glTF model is refused before it is opened: the glTF probe (which
// looks for animations before loading) waited for a FIFO's writer forever and read /dev/zero until memory
// ran out. Under a timeout and a limit on memory, so that a return of either fails the test, not the machine.
TEST(CliRender, AGltfModelThatIsNoRegularFileIsRefusedBeforeReading) {
    auto dir = test::temp_dir("cli-not-regular");
    std::vector<std::filesystem::path> models;
    for (const char* name : {"fifo.glb", "fifo.gltf"}) {
        models.push_back(dir / name);
        ASSERT_EQ(::mkfifo(models.back().c_str(), 0600), 0) << std::strerror(errno);
    }
    for (const char* name : {"zero.glb", "zero.gltf"}) {
        models.push_back(dir / name);
        std::filesystem::create_symlink("/dev/zero", models.back());
    }
    for (const auto& model : models) {
        for (const char* command : {"info", "render"}) {
            std::vector<std::string> args{command, model.string()};
            if (std::string(command) == "render") args.insert(args.end(), {"-o", (dir / "out.png").string()});
            const test::CommandResult r = run_stipple(args, guarded("8000000", 20));
            EXPECT_EQ(r.exit_code, 1) << command << " " << model << ": " << r.err;
            EXPECT_EQ(count_lines(r.err), 1u) << r.err;
            EXPECT_NE(r.err.find(model.string() + ": is not a regular file"), std::string::npos) << r.err;
        }
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
}

// A sparse file of `size` bytes (it takes no disk), for the size checks.
std::filesystem::path sparse_file(const std::filesystem::path& path, uint64_t size) {
    write_file(path, "");
    std::filesystem::resize_file(path, size);
    return path;
}

// A model file too large to load is refused by its size before it is read, in one line naming it, its size
// and the limit: a glTF file of 4 GiB or more (its lengths are 32-bit), and any model file over half the
// machine's memory (a 5 GB .glb grew to 7 GB, a 50 GB .obj ran out of memory saying only that). Under a limit
// on memory, so that a read of one fails the test instead of filling the machine.
TEST(CliRender, AModelFileTooLargeToLoadIsRefusedByItsSize) {
    auto dir = test::temp_dir("cli-too-large");
    const uint64_t half_memory = physical_memory_bytes() / 2;
    ASSERT_GT(half_memory, 0u);
    const std::string beyond_memory = ", more than a model file may be on this machine: " + byte_size(half_memory) + ", half its ";
    const std::pair<const char*, std::string> cases[] = {
        {"big.glb", "a glTF file of 4 GiB or more is not supported"},
        {"big.gltf", "a glTF file of 4 GiB or more is not supported"},
        {"big.obj", beyond_memory}, {"big.ply", beyond_memory}, {"big.stl", beyond_memory}};
    for (const auto& [name, expect] : cases) {
        const bool gltf = expect == cases[0].second;
        const uint64_t size = gltf ? (uint64_t(1) << 32) : half_memory + 1;
        const auto model = sparse_file(dir / name, size);
        for (const char* command : {"info", "render"}) {
            std::vector<std::string> args{command, model.string()};
            if (std::string(command) == "render") args.insert(args.end(), {"-o", (dir / "out.png").string()});
            const test::CommandResult r = run_stipple(args, guarded("4000000", 60));
            EXPECT_EQ(r.exit_code, 1) << command << " " << name << ": " << r.err;
            EXPECT_EQ(count_lines(r.err), 1u) << r.err;
            EXPECT_NE(r.err.find(model.string() + ": is " + byte_size(size)), std::string::npos) << r.err;
            EXPECT_NE(r.err.find(expect), std::string::npos) << r.err;
        }
        std::filesystem::remove(model);
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
}

// A .gltf's external buffers count toward the same limit (half the machine's memory, here made 1 GiB with
// STIPPLE_HOST_MEMORY_LIMIT): a 600-MiB .bin beside a 1-kB .gltf was read whole and, where memory ran out,
// reported with the .gltf's size. Refused before it is read, naming the buffer.
TEST(CliRender, AGltfsExternalBuffersCountTowardItsSize) {
    auto dir = test::temp_dir("cli-large-buffer");
    const uint64_t length = uint64_t(600) << 20;
    sparse_file(dir / "big.bin", length);
    const std::string gltf = R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
        "buffers": [{"uri": "big.bin", "byteLength": )" + std::to_string(length) + R"(}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [0, 0, 0]}]})";
    write_file(dir / "big.gltf", gltf);
    test::ScopedEnv limit("STIPPLE_HOST_MEMORY_LIMIT", "1G");
    const test::CommandResult r = run_stipple({"info", (dir / "big.gltf").string()}, guarded("4000000", 60));
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_EQ(count_lines(r.err), 1u) << r.err;
    EXPECT_NE(r.err.find((dir / "big.gltf").string() + ": buffers[0].uri: 'big.bin' takes the model's files to 600.0 MiB, "
                         "more than a model's files may be on this machine: 512.0 MiB, half its 1.0 GiB of memory"),
              std::string::npos) << r.err;
}

// Memory that runs out while a model loads (here a limit on what the command may map, below a 3 GiB file that
// the size check lets through: the one allocation of its size fails, nothing is read) names the file and its
// size, where main said only "stipple: out of memory".
TEST(CliRender, RunningOutOfMemoryWhileLoadingNamesTheFile) {
    const uint64_t size = uint64_t(3) << 30;
    if (physical_memory_bytes() / 2 < size) GTEST_SKIP() << "a 3 GiB model is refused by its size on this machine";
    if (!kHugePageNew) GTEST_SKIP() << "a sanitizer's shadow memory needs more address space than ulimit -v leaves";
    auto dir = test::temp_dir("cli-out-of-memory");
    for (const char* name : {"big.obj", "big.gltf"}) {
        const auto model = sparse_file(dir / name, size);
        const test::CommandResult r = run_stipple({"info", model.string()}, guarded("2000000", 60));
        EXPECT_EQ(r.exit_code, 1) << r.err;
        EXPECT_EQ(count_lines(r.err), 1u) << r.err;
        EXPECT_NE(r.err.find(model.string() + ": out of memory reading it (3.0 GiB)"), std::string::npos) << r.err;
        std::filesystem::remove(model);
    }
}

// Memory that runs out while generating (here under a 2 GB limit, for 60M stipples, which the machine's memory
// would hold) names the model and the stipples planned in one line; it said a bare "stipple: out of memory".
TEST(CliRender, RunningOutOfMemoryWhileGeneratingNamesTheModel) {
    if (physical_memory_bytes() / 40 < 60'000'000) GTEST_SKIP() << "60M stipples are refused before generating on this machine";
    if (!kHugePageNew) GTEST_SKIP() << "a sanitizer's shadow memory needs more address space than ulimit -v leaves";
    const auto model = test::temp_dir("cli-out-of-memory-generating") / "stack.obj";
    {
        std::ofstream out(model);
        for (int i = 0; i < 200; ++i) out << "v -1 -1 " << i * 1e-3 << "\nv 1 -1 " << i * 1e-3 << "\nv 1 1 " << i * 1e-3 << "\nv -1 1 " << i * 1e-3 << "\n";
        for (int i = 0; i < 200; ++i) out << "f " << 4 * i + 1 << " " << 4 * i + 2 << " " << 4 * i + 3 << " " << 4 * i + 4 << "\n";
    }
    test::ScopedEnv no_cache("STIPPLE_NO_CACHE", "1");
    const test::CommandResult r =
        run_stipple({"info", model.string(), "--dmax", "16", "--max-stipples", "60000000"}, guarded("2000000", 120));
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_EQ(count_lines(r.err), 1u) << r.err;
    EXPECT_NE(r.err.find(model.string() + ": out of memory generating its 60000000 stipples"), std::string::npos) << r.err;
}

// An address-space limit too small for the Vulkan driver is refused in one line before a device is made:
// lavapipe's shader compiler crashed the process under it (exit 139, no message).
TEST(CliRender, AnAddressSpaceTooSmallForTheDriverIsRefused) {
    if (!kHugePageNew) GTEST_SKIP() << "a sanitizer's shadow memory needs more address space than ulimit -v leaves";
    const auto out = test::temp_dir("cli-address-space") / "never.png";
    const test::CommandResult r = run_stipple({"render", "-o", out.string(), "--width", "64", "--height", "48"}, guarded("800000", 60));
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_EQ(count_lines(r.err), 1u) << r.err;
    EXPECT_NE(r.err.find("the address-space limit (ulimit -v) is 781.2 MiB, below the 1.5 GiB"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
}

// A device too small for the object (here made so with STIPPLE_GPU_MEMORY_LIMIT): one line saying what
// the object needs, what the device has and what to lower; no image; never an abort or a lost device.
TEST(CliRender, AnObjectTooBigForTheDeviceIsRefusedInOneLine) {
    const auto out = test::temp_dir("cli-device-limit") / "never.png";
    const test::CommandResult r = [&] {
        test::ScopedEnv limit("STIPPLE_GPU_MEMORY_LIMIT", "2M");
        return test::run_stipple({"render", "-o", out.string(), "--width", "64", "--height", "64"});
    }();
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    for (const char* part : {"blobby.glb: its ", " stipples on ", "of GPU memory, and the device has 2.0 MiB free",
                             "lower --dmax or --max-stipples"})
        EXPECT_NE(r.err.find(part), std::string::npos) << part << " missing in: " << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
    // The objects of a scene count together: under a limit that holds two of the model's objects (each about
    // 12 MiB; each with stipples of its own seed), the third is refused, saying what the others hold (each was
    // checked alone against the whole limit, and a scene of a thousand copies grew to 5 GB).
    const std::string model = test::source_path("assets/blobby.glb");
    nlohmann::json scene = {{"objects", nlohmann::json::array()}}, copies = scene;
    for (int i = 0; i < 5; ++i) {
        scene["objects"].push_back({{"model", model}, {"transform", {{"translate", {3.0 * i, 0.0, 0.0}}}}, {"params", {{"seed", i + 1}}}});
        copies["objects"].push_back({{"model", model}, {"transform", {{"translate", {3.0 * i, 0.0, 0.0}}}}});
    }
    const auto scene_dir = test::temp_dir("cli-device-limit-scene");
    const std::string scene_path = test::write_file(scene_dir / "five.json", scene.dump());
    {  // Copies of one model share its mesh and candidates (ObjectShape): five in 40 MiB, where five of their own need 60.
        const std::string copies_path = test::write_file(scene_dir / "copies.json", copies.dump());
        test::ScopedEnv env("STIPPLE_GPU_MEMORY_LIMIT", "40M");
        const test::CommandResult five = test::run_stipple({"render", copies_path, "-o", out.string(), "--width", "64", "--height", "64"});
        EXPECT_EQ(five.exit_code, 0) << five.err;
        // Vector output adds a list of each object's visible stipples (20 bytes a candidate), most of a copy's
        // need: the refusal counts it in and says so (it named a spot's 2.8 MiB where 13.3 were needed).
        const auto svg = std::filesystem::path(copies_path).parent_path() / "never.svg";
        const test::CommandResult vector = test::run_stipple({"render", copies_path, "-o", svg.string(), "--width", "64", "--height", "64"});
        EXPECT_EQ(vector.exit_code, 1) << vector.err;
        for (const char* part : {"MiB of it vector output's list of its visible stipples", "or write a PNG"})
            EXPECT_NE(vector.err.find(part), std::string::npos) << part << " missing in: " << vector.err;
    }
    for (const auto& [limit, refused] : {std::pair<const char*, bool>{"30M", true}, {"80M", false}}) {
        test::ScopedEnv env("STIPPLE_GPU_MEMORY_LIMIT", limit);
        const test::CommandResult five = test::run_stipple({"render", scene_path, "-o", out.string(), "--width", "64", "--height", "64"});
        EXPECT_EQ(five.exit_code, refused ? 1 : 0) << limit << ": " << five.err;
        if (refused) {  // the scene's line: the object, what the others take, and what to lower in a scene file
            EXPECT_EQ(std::count(five.err.begin(), five.err.end(), '\n'), 1) << five.err;
            for (const std::string& part : std::vector<std::string>{scene_path + ": objects[2] (" + model + ") needs about ", " the objects before it take",
                                           "fewer objects, or lighter ones (a lower \"dmax\""})
                EXPECT_NE(five.err.find(part), std::string::npos) << part << " missing in: " << five.err;
        }
    }
    {  // Vector output that also draws the screen's frame holds the scene twice, and says so.
        test::ScopedEnv env("STIPPLE_GPU_MEMORY_LIMIT", "80M");
        const auto svg = std::filesystem::path(scene_path).parent_path() / "never.svg";
        const test::CommandResult twice = test::run_stipple({"render", scene_path, "-o", svg.string(), "--width", "64", "--height", "64", "--stats"});
        EXPECT_EQ(twice.exit_code, 1) << twice.err;
        EXPECT_NE(twice.err.find("(held twice: vector output with --stats"), std::string::npos) << twice.err;
    }
    std::filesystem::remove(out);
    // A size that is not one is refused, not ignored (a typo would test nothing).
    for (const char* bad : {"foo", "0", "-1", "2X", "99999999999G"}) {
        test::ScopedEnv env("STIPPLE_GPU_MEMORY_LIMIT", bad);
        const test::CommandResult e = test::run_stipple({"render", "-o", out.string(), "--width", "64", "--height", "64"});
        EXPECT_EQ(e.exit_code, 1) << bad;
        EXPECT_EQ(std::count(e.err.begin(), e.err.end(), '\n'), 1) << e.err;
        EXPECT_NE(e.err.find(std::string("STIPPLE_GPU_MEMORY_LIMIT=") + bad + " is not a size"), std::string::npos) << e.err;
    }
}

// A device may allow as few as 4096 memory allocations at once (maxMemoryAllocationCount). Small buffers
// share blocks (gpu::MemoryPool): eight copies of the default model draw within 80 (lavapipe: 58), where with an
// allocation a buffer they took about 175; under fewer the scene is refused in one line naming the object, not a
// validation error or a crash (a null pool in the refusal crashed it when first written).
TEST(CliRender, ASceneBeyondTheDevicesAllocationsIsRefusedInOneLine) {
    const std::string model = test::source_path("assets/blobby.glb");
    nlohmann::json scene = {{"objects", nlohmann::json::array()}};
    for (int i = 0; i < 8; ++i)
        scene["objects"].push_back({{"model", model}, {"transform", {{"translate", {3.0 * i, 0.0, 0.0}}}}, {"params", {{"dmax", 0.05}}}});
    const auto dir = test::temp_dir("cli-allocation-limit");
    const std::string scene_path = test::write_file(dir / "eight.json", scene.dump());
    const auto out = dir / "eight.png";
    const auto render = [&](const char* limit) {
        test::ScopedEnv env("STIPPLE_GPU_ALLOCATION_LIMIT", limit);
        return test::run_stipple({"render", scene_path, "-o", out.string(), "--width", "64", "--height", "64"});
    };
    const test::CommandResult fits = render("80");
    EXPECT_EQ(fits.exit_code, 0) << fits.err;
    EXPECT_TRUE(std::filesystem::exists(out));
    std::filesystem::remove(out);
    const test::CommandResult refused = render("20");
    EXPECT_EQ(refused.exit_code, 1) << refused.err;
    EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << refused.err;
    for (const std::string& part : std::vector<std::string>{scene_path + ": objects[", "(" + model + "): this device allows 20 GPU memory allocations",
                                                            "draw fewer objects"})
        EXPECT_NE(refused.err.find(part), std::string::npos) << part << " missing in: " << refused.err;
    EXPECT_FALSE(std::filesystem::exists(out));
    test::ScopedEnv env("STIPPLE_GPU_ALLOCATION_LIMIT", "-5");
    const test::CommandResult typo = test::run_stipple({"render", "-o", out.string(), "--width", "64", "--height", "64"});
    EXPECT_EQ(typo.exit_code, 1);
    EXPECT_NE(typo.err.find("STIPPLE_GPU_ALLOCATION_LIMIT=-5 is not a count"), std::string::npos) << typo.err;
}

// The count of stipples is known before they are made (planned_stipple_count), so an object the device
// cannot hold is refused before its generation, not after it (until 2026-12-05 igea at --dmax 16
// --max-stipples 1e8 generated for 192 s to be refused): nothing reaches the stipple cache, and the count
// the refusal names is the one generation makes (info's, here made under no limit), the stretch headroom
// of an animated model included.
TEST(CliRender, AnObjectTooBigForTheDeviceIsRefusedBeforeItsStipplesAreMade) {
    const auto dir = test::temp_dir("cli-refused-before-generation");
    std::vector<std::string> models = {test::source_path("assets/blobby.glb")};
    if (const std::string fox = test::shared_model("fox.glb"); !fox.empty())
        models.push_back(fox);
    else
        std::printf("../shared/models/fox.glb is absent: the animated model's case is skipped\n");
    for (const std::string& model : models) {
        const auto cache = dir / ("cache-" + std::filesystem::path(model).stem().string());
        std::filesystem::create_directories(cache);
        test::ScopedEnv cache_dir("STIPPLE_CACHE_DIR", cache.string());
        // A seed no other test uses: the cache cannot hold these stipples from before.
        const std::vector<std::string> params = {"--dmax", "1.5", "--seed", "424242"};
        std::vector<std::string> render = {"render", model, "-o", (dir / "never.png").string()};
        std::vector<std::string> tone = {"tone", model, "--frames", "1"};
        render.insert(render.end(), params.begin(), params.end());
        tone.insert(tone.end(), params.begin(), params.end());
        std::optional<test::ScopedEnv> small(std::in_place, "STIPPLE_MAX_STORAGE_BUFFER", "1M");
        for (const auto& command : {render, tone}) {
            const test::CommandResult r = run_stipple(command);
            EXPECT_EQ(r.exit_code, 1) << command[0] << ": " << r.err;
            EXPECT_EQ(count_lines(r.err), 1u) << r.err;
            EXPECT_NE(r.err.find("this device's largest is 1.0 MiB: lower --dmax or --max-stipples"), std::string::npos) << r.err;
            EXPECT_TRUE(std::filesystem::is_empty(cache)) << command[0] << " " << model << " generated before refusing";
        }
        small.reset();
        std::vector<std::string> info = {"info", model};
        info.insert(info.end(), params.begin(), params.end());
        const test::CommandResult made = run_stipple(info);
        ASSERT_EQ(made.exit_code, 0) << made.err;
        const size_t at = made.out.find("stipple candidates:");
        ASSERT_NE(at, std::string::npos) << made.out;
        const unsigned long long generated = std::stoull(made.out.substr(at + std::strlen("stipple candidates:")));
        EXPECT_GT(generated, 100000u);
        const test::CommandResult refused = [&] {
            test::ScopedEnv again("STIPPLE_MAX_STORAGE_BUFFER", "1M");
            return run_stipple(render);
        }();
        EXPECT_NE(refused.err.find(": its " + std::to_string(generated) + " stipples on "), std::string::npos)
            << "info made " << generated << "; " << refused.err;
    }
    // Vector output's list of visible stipples (20 bytes a candidate) and a scene's objects together are
    // checked before generation too: the default model's 735,511 candidates fit an 8 MiB buffer as drawing
    // needs them (8 bytes each) but not as vector output's list; two objects of it with stipples of their own
    // (two seeds: copies would share their mesh and candidates) fit a 14 MiB device one at a time (about 8 MiB
    // each) but not together. From a scene file, the list's refusal names the file and the object, and says what
    // to lower in its params.
    const std::string blobby = test::source_path("assets/blobby.glb");
    const auto cache = dir / "cache-vector-and-scene";
    std::filesystem::create_directories(cache);
    test::ScopedEnv cache_dir("STIPPLE_CACHE_DIR", cache.string());
    {
        test::ScopedEnv small("STIPPLE_MAX_STORAGE_BUFFER", "8M");
        const test::CommandResult r = run_stipple({"render", blobby, "--seed", "424243", "-o", (dir / "never.svg").string()});
        EXPECT_EQ(r.exit_code, 1) << r.err;
        EXPECT_EQ(count_lines(r.err), 1u) << r.err;
        EXPECT_NE(r.err.find("vector output of 735511 candidate stipples needs a 14.0 MiB list"), std::string::npos) << r.err;
        EXPECT_TRUE(std::filesystem::is_empty(cache)) << "vector output generated before refusing";
    }
    {
        // A mesh whose polygons alone exceed the largest buffer (16 bytes each): no stipple option helps, and
        // the refusal says so (an 8.7M-triangle model was told to lower --dmax).
        test::ScopedEnv small("STIPPLE_MAX_STORAGE_BUFFER", "512k");
        const test::CommandResult r =
            run_stipple({"render", blobby, "--dmax", "0", "--silhouette-lines", "-o", (dir / "never.png").string()});
        EXPECT_EQ(r.exit_code, 1) << r.err;
        EXPECT_EQ(count_lines(r.err), 1u) << r.err;
        EXPECT_NE(r.err.find("the mesh is too large for this device (at most 32768 polygons and 43690 vertices): use a "
                             "simplified model"),
                  std::string::npos) << r.err;
        EXPECT_EQ(r.err.find("--dmax"), std::string::npos) << r.err;
    }
    {
        // Vector output with --stats holds the objects twice (the screen frame's renderer and the export's)
        // and the list (about 12 + 12 + 14 MiB here): refused under 30 MiB, which holds one copy and the list.
        test::ScopedEnv memory("STIPPLE_GPU_MEMORY_LIMIT", "30M");
        const test::CommandResult r = run_stipple({"render", blobby, "--seed", "424243", "-o", (dir / "never.svg").string(),
                                                   "--width", "320", "--height", "256", "--stats"});
        EXPECT_EQ(r.exit_code, 1) << r.err;
        EXPECT_NE(r.err.find("(held twice: vector output with --stats, --mask or --repeat draws the screen's frame too)"),
                  std::string::npos) << r.err;
        EXPECT_NE(r.err.find("a lower --dmax or --max-stipples"), std::string::npos) << r.err;
        EXPECT_TRUE(std::filesystem::is_empty(cache)) << "vector output with --stats generated before refusing";
    }
    nlohmann::json scene = {{"objects", nlohmann::json::array()}};
    for (int i = 0; i < 2; ++i)
        scene["objects"].push_back({{"model", blobby}, {"params", {{"seed", 424243 + i}}}, {"transform", {{"translate", {3.0 * i, 0.0, 0.0}}}}});
    const std::string scene_path = test::write_file(dir / "two.json", scene.dump());
    {
        test::ScopedEnv small("STIPPLE_MAX_STORAGE_BUFFER", "8M");
        const test::CommandResult r = run_stipple({"render", scene_path, "-o", (dir / "never.svg").string()});
        EXPECT_EQ(r.exit_code, 1) << r.err;
        EXPECT_EQ(count_lines(r.err), 1u) << r.err;
        for (const std::string& part : {scene_path + ": objects[0] (" + blobby + "): vector output of 735511 candidate",
                                       std::string("a lower \"dmax\" or \"max_stipples\" in its params, or write a PNG")})
            EXPECT_NE(r.err.find(part), std::string::npos) << part << " missing in: " << r.err;
    }
    for (const auto& [limit, refused] : {std::pair<const char*, bool>{"14M", true}, {"40M", false}}) {
        test::ScopedEnv memory("STIPPLE_GPU_MEMORY_LIMIT", limit);
        const test::CommandResult r = run_stipple({"render", scene_path, "-o", (dir / "two.png").string(), "--width", "64", "--height", "64"});
        EXPECT_EQ(r.exit_code, refused ? 1 : 0) << limit << ": " << r.err;
        if (!refused) continue;
        EXPECT_NE(r.err.find(scene_path + ": objects[1] ("), std::string::npos) << r.err;
        EXPECT_TRUE(std::filesystem::is_empty(cache)) << "the scene generated before refusing";
    }
    EXPECT_FALSE(std::filesystem::is_empty(cache)) << "the scene that fits was drawn from generated stipples";
}

std::string file_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// A dispatch wider than the device allows along x (65535 groups on lavapipe: 4.2M polygons at 64 a group,
// 16.8M pixels for the depth words' coverage) goes in rows along y (gpu::dispatch_groups, shaders/dispatch.h);
// until 2026-12-04 such a model drew with validation errors and undefined results. Made so here with
// STIPPLE_MAX_WORKGROUPS=3 on the default scene: every pass dispatched over polygons, edges, pixel words or a
// list then runs in rows, and draws exactly what one row does, on every path and line kind.
TEST(CliRender, WideDispatchesGoInRowsAndDrawTheSame) {
    const auto dir = test::temp_dir("cli-dispatch-rows");
    const std::vector<std::vector<std::string>> variants = {
        {"--density-path", "vertex", "--contours", "--borders", "--creases"},
        {"--density-path", "indirect", "--silhouette-lines"},
        {"--density-path", "splat", "--contours", "--depth-raster", "compute", "--depth-cull", "on"},
        {"--density-path", "cpu-splat", "--creases"},
        {"--density-path", "cpu", "--toon"},
    };
    for (size_t v = 0; v < variants.size(); ++v) {
        std::string images[2];
        for (int rows = 0; rows < 2; ++rows) {
            images[rows] = (dir / ("v" + std::to_string(v) + (rows ? "_rows.png" : ".png"))).string();
            std::vector<std::string> args{"render", "-o", images[rows], "--width", "320", "--height", "256"};
            args.insert(args.end(), variants[v].begin(), variants[v].end());
            std::optional<test::ScopedEnv> in_rows;
            if (rows) in_rows.emplace("STIPPLE_MAX_WORKGROUPS", "3");
            const test::CommandResult r = test::run_stipple(args);
            ASSERT_EQ(r.exit_code, 0) << r.err;
        }
        const std::string one = file_bytes(images[0]), in_rows = file_bytes(images[1]);
        ASSERT_GT(one.size(), 1000u);
        EXPECT_TRUE(one == in_rows) << variants[v][1] << ": the drawing in rows differs from the drawing in one row";
    }
    for (const char* bad : {"abc", "0", "-3", "7x"}) {
        test::ScopedEnv env("STIPPLE_MAX_WORKGROUPS", bad);
        const test::CommandResult e = test::run_stipple({"render", "-o", (dir / "never.png").string()});
        EXPECT_EQ(e.exit_code, 1) << bad;
        EXPECT_EQ(std::count(e.err.begin(), e.err.end(), '\n'), 1) << e.err;
        EXPECT_NE(e.err.find(std::string("STIPPLE_MAX_WORKGROUPS=") + bad + " is not a workgroup count"), std::string::npos) << e.err;
    }
    for (const char* bad : {"abc", "0", "-3"}) {  // read as decimal counts too (until 2026-12-04 ignored)
        test::ScopedEnv env("STIPPLE_THREADS", bad);
        const test::CommandResult e = test::run_stipple({"render", "-o", (dir / "never.png").string()});
        EXPECT_EQ(e.exit_code, 1) << bad;
        EXPECT_NE(e.err.find(std::string("STIPPLE_THREADS=") + bad + " is not a thread count"), std::string::npos) << e.err;
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "never.png"));
}

// STIPPLE_VALIDATION and STIPPLE_NO_CACHE are 1 or 0: "yes" or "off" read as set (anything but "0") and
// hid a typo.
TEST(CliRender, OnOffSettingsAreOneOrZero) {
    const auto out = test::temp_dir("cli-validation-env") / "never.png";
    for (const char* setting : {"STIPPLE_VALIDATION", "STIPPLE_NO_CACHE"}) {
        for (const char* bad : {"yes", "off", "2"}) {
            test::ScopedEnv env(setting, bad);
            const test::CommandResult e = test::run_stipple({"render", "-o", out.string(), "--width", "64", "--height", "64"});
            EXPECT_EQ(e.exit_code, 1) << setting << "=" << bad;
            EXPECT_EQ(std::count(e.err.begin(), e.err.end(), '\n'), 1) << e.err;
            EXPECT_NE(e.err.find(std::string(setting) + "=" + bad + " must be 1"), std::string::npos) << e.err;
        }
    }
    EXPECT_FALSE(std::filesystem::exists(out));
}

// The fraction of pixels darker than mid-grey in each quarter of the image (top left, top right, bottom
// left, bottom right).
std::array<double, 4> ink_by_quarter(const Image& image) {
    std::array<double, 4> inked{};
    const int w = image.width, h = image.height;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (image.pixels[(size_t(y) * w + x) * image.channels] < 128) inked[(y >= h / 2 ? 2 : 0) + (x >= w / 2 ? 1 : 0)] += 1.0;
    for (double& q : inked) q /= double(w / 2) * double(h / 2);
    return inked;
}

// Wide Raskar-Cohen lines drawn in tiles join as in one frame: their round caps are points, which a tile drops
// where their centre lies in the next one, so the tiles overlap by half the line's width (42 pixels of a 48-px
// outline were missing along a seam).
TEST(CliRender, WideOutlinesJoinAcrossTiles) {
    const auto dir = test::temp_dir("cli-tiled-outline");
    const std::string tiled = (dir / "tiled.png").string(), whole = (dir / "whole.png").string();
    const std::vector<std::string> common = {"render", "--width", "2000", "--height", "1500", "--dmax", "0", "--silhouette-lines",
                                             "--silhouette-width", "48", "--no-thinning", "--distance", "1.3"};
    std::vector<std::string> a = common, b = common;
    a.insert(a.end(), {"-o", whole});
    b.insert(b.end(), {"-o", tiled});
    const test::CommandResult one = run_stipple(a);
    ASSERT_EQ(one.exit_code, 0) << one.err;
    const test::CommandResult many = [&] {
        test::ScopedEnv small_buffers("STIPPLE_MAX_STORAGE_BUFFER", "6M");  // tiles of 1254 px, as above
        return run_stipple(b);
    }();
    ASSERT_EQ(many.exit_code, 0) << many.err;
    const Image x = read_png(whole), y = read_png(tiled);
    ASSERT_EQ(x.pixels.size(), y.pixels.size());
    size_t differing = 0, inked = 0;
    for (size_t i = 0; i < x.pixels.size(); i += 4) {
        differing += std::abs(int(x.pixels[i]) - int(y.pixels[i])) > 2;
        inked += x.pixels[i] < 128;
    }
    std::printf("48-px outline: %zu of %zu inked pixels differ between one frame and tiles\n", differing, inked);
    EXPECT_GT(inked, 50000u);
    EXPECT_LE(differing, 16u);  // 6 measured; 42 when the tiles overlapped by the dots' reach alone
}

// An image whose pixel words do not fit the device's largest storage buffer (the splat's, here made so with
// STIPPLE_MAX_STORAGE_BUFFER; lavapipe's is 128 MiB, 5792x5792 pixels) is drawn in tiles, as a print is:
// the same drawing as one frame, without a validation message; what needs one frame says so in one line.
TEST(CliRender, ImagesLargerThanOneFrameAreDrawnInTiles) {
    const auto dir = test::temp_dir("cli-tiled");
    const std::string tiled = (dir / "tiled.png").string(), whole = (dir / "whole.png").string();
    const test::CommandResult one = run_stipple({"render", "-o", whole, "--width", "2000", "--height", "1500", "--stats"});
    ASSERT_EQ(one.exit_code, 0) << one.err;
    // 1,572,864 pixels (the default scene's own buffers need 5.6 MiB): tiles of 1254 x 1254, 2 x 2 of them.
    std::optional<test::ScopedEnv> small_buffers(std::in_place, "STIPPLE_MAX_STORAGE_BUFFER", "6M");
    const test::CommandResult r = run_stipple({"render", "-o", tiled, "--width", "2000", "--height", "1500", "--stats"});
    const test::CommandResult mask = run_stipple(
        {"render", "-o", tiled + ".x.png", "--width", "2000", "--height", "1500", "--mask", (dir / "m.png").string()});
    const test::CommandResult svg = run_stipple({"render", "-o", (dir / "x.svg").string(), "--width", "2000", "--height", "1500"});
    const test::CommandResult tone = run_stipple({"tone", "--width", "2000", "--height", "1500", "--frames", "1"});
    // A frame that fits, but whose list of visible stipples (20 bytes a candidate, where drawing needs 8)
    // does not: refused in one line (until 2026-12-04 the descriptor reached past the buffer's range).
    const test::CommandResult small_svg = run_stipple({"render", "-o", (dir / "y.svg").string(), "--width", "320", "--height", "256"});
    small_buffers.reset();
    EXPECT_EQ(small_svg.exit_code, 1);
    EXPECT_EQ(count_lines(small_svg.err), 1u) << small_svg.err;
    EXPECT_NE(small_svg.err.find("candidate stipples needs a 14.0 MiB list, and this device's largest buffer is 6.0 MiB"), std::string::npos) << small_svg.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "y.svg"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.find("validation"), std::string::npos) << r.err;
    EXPECT_NE(r.out.find("not measured (drawn in tiles)"), std::string::npos) << r.out;
    // The drawn stipples are the image's, not the last tile's: counted, every tile draws every polygon's (culled
    // to its own viewport the corner tile counted 0 of a 6000 x 6000 image's).
    auto drawn_in = [](const std::string& out) {
        const size_t at = out.find("drawn stipples:");
        return at == std::string::npos ? -1LL : std::stoll(out.substr(at + std::strlen("drawn stipples:")));
    };
    EXPECT_GT(drawn_in(one.out), 10000);
    EXPECT_EQ(drawn_in(r.out), drawn_in(one.out)) << r.out;
    const Image a = read_png(tiled), b = read_png(whole);
    ASSERT_EQ(a.width, 2000);
    ASSERT_EQ(a.height, 1500);
    // Every tile drawn where it belongs: the drawing the same as one frame's, quarter by quarter (the tiles'
    // seams fall at 1254 pixels, inside the right and the bottom quarters).
    const std::array<double, 4> qa = ink_by_quarter(a), qb = ink_by_quarter(b);
    for (int q = 0; q < 4; ++q) {
        std::printf("quarter %d: ink %.4f tiled, %.4f one frame\n", q, qa[q], qb[q]);
        ASSERT_GT(qb[q], 0.01) << "the default scene reaches every quarter";
        EXPECT_NEAR(qa[q] / qb[q], 1.0, 0.01) << "quarter " << q;
    }
    size_t differ = 0;
    for (size_t i = 0; i < a.pixels.size(); i += 4) differ += (a.pixels[i] < 128) != (b.pixels[i] < 128);
    std::printf("pixels inked differently: %zu of %d\n", differ, a.width * a.height);
    EXPECT_LT(double(differ), 1e-3 * a.width * a.height);
    for (const test::CommandResult* refused : {&mask, &svg}) {
        EXPECT_EQ(refused->exit_code, 1);
        EXPECT_EQ(count_lines(refused->err), 1u) << refused->err;
        EXPECT_NE(refused->err.find("is drawn in tiles on this device"), std::string::npos) << refused->err;
    }
    EXPECT_NE(mask.err.find("--mask"), std::string::npos);
    // tone draws whole frames: refused by the renderer, in one line, before any Vulkan error.
    EXPECT_EQ(tone.exit_code, 1);
    EXPECT_EQ(tone.err.find("validation"), std::string::npos) << tone.err;
    EXPECT_NE(tone.err.find("more than this device's largest storage buffer"), std::string::npos) << tone.err;
}

TEST(CliRender, BadParametersAreRejectedClearly) {
    struct Case {
        std::vector<std::string> args;
        const char* expect;
    };
    const Case cases[] = {
        {{"render", "--dmax", "-1"}, "--dmax"},
        {{"render", "--dmax", "abc"}, "--dmax"},
        {{"render", "--point-size", "1000"}, "--point-size"},
        {{"render", "--width", "0"}, "--width"},
        {{"render", "--light", "0,0,0"}, "--light"},
        {{"render", "--light", "1,2"}, "--light"},
        {{"render", "--shading-exponent", "0"}, "--shading-exponent"},
        {{"render", "--frobnicate"}, "--frobnicate"},
        {{"render", "--device", "99"}, "--device"},
        {{"render", "--distance", "1e-300"}, "--distance = 1e-300"},
        // A camera inside any model, its projection degenerate: every candidate was counted drawn on a blank frame.
        {{"render", "--distance", "1e-20"}, "--distance = 1e-20 must be in [0.0001, 10000]"},
        {{"render", "--pitch", "100"}, "--pitch = 100"},
        {{"render", "--fill-paper"}, "--fill-paper paints the page of vector output"},
        {{"tone", "--arc", "40"}, "--arc turns the object"},
        {{"tone", "--distances", "1,2,"}, "--distances '1,2,' has an empty entry"},
        {{"tone", "--seeds", "1,2,"}, "--seeds '1,2,' has an empty entry"},
        {{"tone", "--views", "30:10,"}, "--views '30:10,' has an empty entry"},
        {{"render", "--yaw", "1e30"}, "--yaw = 1e30"},
        {{"render", "-o", "a.png", "-o", "b.png"}, "option -o given twice (a.png and b.png)"},
        {{"render", "-o", "a.png", "--output", "b.png"}, "name the output twice"},
        {{"tone", "--distances", "1,1e-300"}, "--distances: 1e-300"},
        {{"render", "--device", "-1"}, "--device = -1"},
        {{"render", "--device", "4294967296"}, "--device = 4294967296"},
        {{"tone", "--device", "-2"}, "--device = -2"},
        {{"render", "-o", "x.jpg"}, "-o x.jpg: the output is named by its extension"},
        // An output that cannot be written is named before the model is read and drawn (it was named after).
        {{"render", "-o", "/proc/x.png"}, "-o /proc/x.png: cannot write there: "},
        {{"render", "-o", "/proc/x.svg"}, "-o /proc/x.svg: cannot write there: "},
        {{"render", "--mask", "/proc/m.png"}, "--mask /proc/m.png: cannot write there: "},
        {{"render", "-o", "/dev/null/x.png"}, "-o /dev/null/x.png: cannot make its folder /dev/null: "},
        {{"render", "-o", "/"}, "-o /: the output is named by its extension"},
        {{"render", "-o", ""}, "the output is named by its extension"},
        {{"render", "-o", "same.png", "--mask", "same.png"}, "is the image's own path"},
        {{"render", "-o", "./same.png", "--mask", "same.png"}, "is the image's own path"},
        {{"render", "-o", "fq/%d.png", "--mask", "fq/%01d.png", "--frames", "2"}, "is the image's own path"},
        {{"render", "-o", "fq/%d.png", "--mask", "fq/%02d.png", "--frames", "11", "--orbit", "30"}, "names the file of an image of -o fq/%d.png for frame 10"},
        {{"render", "--mask", "m.svg"}, "--mask m.svg"},
        {{"tone", "--images", ""}, "--images needs a folder"},
        {{"tone", "--images", "/etc/passwd"}, "--images /etc/passwd is not a folder"},
        {{"render", "--dmax", "1e-300"}, "--dmax = 1e-300 is out of range"},
        // Beyond a double too (it read as 0 and was taken); 0 offered only where the range has it; an integer's
        // fraction shown as given (single precision rounded it away: "4294967296 is not an integer").
        {{"render", "--dmax", "1e-400"}, "--dmax = 1e-400 is out of range: it must be >= 0 and <= 16 (single precision holds it as 0: give 0, or at least 1e-38)"},
        {{"render", "--de", "1e-46"}, "--de = 1e-46 is out of range: it must be > 0 and <= 16 (single precision holds it as 0: give at least 1e-38)"},
        {{"render", "--seed", "4294967295.5"}, "--seed = 4294967295.5 is not an integer"},
        {{"render", "--light", "1e300,0,0"}, "has a number beyond single precision"},
        {{"render", "-o", "x.svg", "--page", "5x5mm"}, "smaller than 10 mm a side"},
        {{"render", "-o", "x.png", "--page", "A4", "--dpi", "300", "--dot-style", "circle"},
         "--dot-style sets how SVG or PDF output draws its dots; a print image (--dpi) draws them as the screen does"},
        {{"render", "-o", "x.png", "--page", "A4", "--dpi", "300", "--pen-width", "0.5"}, "--pen-width sets the pen of SVG or PDF output's lines and dots; a print image"},
        // A PNG is pointed at the outputs that take them (it named CSV and print images, which refuse them too).
        {{"render", "-o", "x.png", "--dot-style", "tick"}, "--dot-style sets how SVG or PDF output draws its dots: give -o x.svg or x.pdf"},
        {{"render", "-o", "x.png", "--pen-width", "0.3"}, "--pen-width sets the pen of SVG or PDF output's lines and dots: give"},
        {{"render", "-o", "x.png", "--page", "A4", "--dpi", "300", "--fill-paper"}, "a print image has its paper"},
        {{"render", "-o", "x.png", "--page", "A4", "--dpi", "300", "--width", "20000"}, "--width/--height must be between 1 and 16384"},
        {{"render", "-o", "x.png", "--page", "A3", "--dpi", "2400"}, "more than a PNG of 2 GiB of pixels"},
        {{"bench", "--out", ""}, "--out needs a folder"},
        {{"info", "--cache-dir", ""}, "--cache-dir needs a folder"},
        {{"cache", "--list", "--cache-dir", "/nonexistent/stipple-cache"}, "no such folder"},
        {{"cache", "--clear", "--cache-dir", "/etc/passwd"}, "is not a folder"},
        {{"render", "--depth-cull", "sometimes"}, "--depth-cull"},
        {{"render", "--repeat", "2", "--queued", "0"}, "--queued"},
        {{"render", "--queued", "2"}, "--repeat"},
        {{"bench", "--depth-cull", "1"}, "--depth-cull"},
        {{"view", "--depth-cull", "often"}, "--depth-cull"},
        // Taken as no benchmark, it left the window open under a script that waited for the figure.
        {{"view", "--benchmark-frames", "0"}, "--benchmark-frames = 0 must be in 1..1000000"},
        // Checked when the viewer starts (a folder failed only at Ctrl+S, and x.png took the scene's JSON).
        {{"view", "--save-scene", "x.png"}, "--save-scene x.png: a scene file is named .json"},
        {{"view", "--save-scene", "/proc/s.json"}, "--save-scene /proc/s.json: cannot write there"},
        {{"info"}, "MODEL"},
        {{"parity", "--devices", "0,99"}, "--devices"},
        {{"parity", "--devices", "0"}, "--devices"},
        {{"parity", "--devices", "0,1,2"}, "--devices needs two device indices"},  // not "'1' is not a device"
        {{"cache", "--list", "--clear"}, "--list or --clear, not both"},
        {{"render", "-o", "x.svg", "--dpi", "300"}, "--dpi is for PNG output"},  // not "--dpi needs --page"
        {{"render", "-o", "x.svg", "--tile", "512"}, "--tile is for print-resolution PNG output"},  // not "give --dpi too"
        {{"render", "-o", "x.csv", "--fill-paper"}, "a CSV (x.csv) has no page"},
        {{"render", "-o", "x.csv", "--dot-style", "tick"}, "--dot-style sets how SVG or PDF output draws its dots; a CSV (x.csv) lists"},
        {{"render", "-o", "x.csv", "--pen-width", "0.3"}, "--pen-width sets the pen of SVG or PDF output's lines and dots; a CSV"},
        {{"parity", "--devices", "0,0", "--paths", "splat,fast"}, "--paths"},
        {{"parity", "--devices", "0,0", "--yaws", "0"}, "--yaws"},
        {{"parity", "--yaws", "0"}, "--yaws"},  // said before the count of devices (lavapipe alone: one)
        {{"parity", "--paths", "foo"}, "--paths: unknown density path 'foo'"},
        {{"parity", "--paths", "splat,vertex,splat"}, "--paths: 'splat' is named twice"},  // drew its rows twice
        {{"parity", "--devices", "0,0", "--density-path", "cpu"}, "--density-path does not apply"},
        // Numbers are decimal everywhere: hex was read by some options (--seed 0x10 as 16) and not others.
        {{"render", "--seed", "0x10"}, "--seed: '0x10' is not an integer"},
        {{"render", "--ink", "1,0"}, "is not three numbers R,G,B"},
        {{"render", "--dmax", "0x0.4p0"}, "--dmax: '0x0.4p0' is not a finite number"},
        {{"render", "--width", " 320"}, "--width: ' 320' is not an integer"},
        {{"render", "--light", "0x1,0,1"}, "is not three numbers X,Y,Z"},
        {{"render", "--light", "1,0,1,"}, "is not three numbers X,Y,Z"},
        {{"render", "--ink", "red"}, "--ink: 'red' is not a colour (#rrggbb, #rgb, or R,G,B each in 0..1)"},
        {{"render", "--ink", "#12345"}, "--ink: '#12345' is not a colour"},
        {{"render", "--ink", "100"}, "--ink: '100' is not a colour: write #100 for hex digits"},
        {{"render", "--paper", "1.5,0,0"}, "--paper: '1.5,0,0' is not a colour: each of R,G,B must be in 0..1"},
        {{"view", "--paper", "1,0"}, "--paper: '1,0' is not three numbers"},
        {{"tone", "--distances", "0x10"}, "--distances: '0x10' is not a finite number"},
        {{"tone", "--views", "30:10,30.01:10"}, "is the same view as an earlier one to 0.1 degree"},
        {{"tone", "--views", "30.05:10,30.05:10"}, "is the same view as an earlier one to 0.1 degree"},
    };
    for (const Case& c : cases) {
        auto result = run_stipple(c.args);
        EXPECT_NE(result.exit_code, 0) << c.args.back();
        EXPECT_EQ(count_lines(result.err), 1u) << result.err;
        EXPECT_NE(result.err.find(c.expect), std::string::npos) << result.err;
    }
    // A folder named as the output is refused; an existing file, a pipe and a link are never opened by the
    // check (a pipe would block it, a dangling link would have a file made where it points): the run goes on to
    // the model, missing here, and leaves them as they were.
    const std::filesystem::path dir = test::temp_dir("cli-output-writable");
    std::filesystem::create_directories(dir / "folder.png");
    auto folder = run_stipple({"render", "-o", (dir / "folder.png").string()});
    EXPECT_EQ(folder.exit_code, 1);
    EXPECT_NE(folder.err.find("folder.png: is a folder, not a file"), std::string::npos) << folder.err;
    write_file((dir / "kept.png").string(), "not a png");
    ASSERT_EQ(mkfifo((dir / "pipe.png").c_str(), 0600), 0);
    std::filesystem::create_symlink(dir / "nowhere" / "target.png", dir / "link.png");
    const std::string missing = (dir / "missing.obj").string();
    for (const char* name : {"kept.png", "pipe.png", "link.png"}) {
        auto r = run_stipple({"render", missing, "-o", (dir / name).string()});
        EXPECT_EQ(r.exit_code, 1) << name;
        EXPECT_NE(r.err.find("missing.obj"), std::string::npos) << name << ": " << r.err;
    }
    std::ifstream in(dir / "kept.png");
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()), "not a png");
    EXPECT_FALSE(std::filesystem::exists(dir / "nowhere")) << "the check made the link's target";
    EXPECT_TRUE(std::filesystem::is_fifo(dir / "pipe.png"));

    // Missing folders are made by the writer, not the check (a refused request left them behind), so the check
    // says before the model is read what would stop the writer: a folder that is a link to nothing, or a file.
    std::filesystem::create_directory_symlink(dir / "gone", dir / "dangling");
    auto dangling = run_stipple({"render", missing, "-o", (dir / "dangling" / "sub" / "x.png").string()});
    EXPECT_EQ(dangling.exit_code, 1);
    EXPECT_NE(dangling.err.find("dangling is a link to nothing"), std::string::npos) << dangling.err;
    auto under_file = run_stipple({"render", missing, "-o", (dir / "kept.png" / "sub" / "x.png").string()});
    EXPECT_EQ(under_file.exit_code, 1);
    EXPECT_NE(under_file.err.find("kept.png is not a folder"), std::string::npos) << under_file.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "gone"));
}

// --stats says how many triangles the depth pass drew: all of them with --depth-cull off, fewer with on
// for the default scene seen from afar (its triangles then cover a few pixels at most).
// Generation and drawing multiply coordinates together in single precision: a triangle 1e10 across made
// NaN positions in the relaxation (a crash), one 1e-8 across drew nothing (the camera's floor on the
// radius). Within the range the loader accepts (mesh.hpp kMaxCoordinate, kMinExtent) a triangle draws the
// same stipples at every size; beyond it the loader says so in one line.
TEST(CliRender, ATriangleDrawsTheSameAtEverySize) {
    const std::filesystem::path dir = test::temp_dir("cli-scale");
    auto drawn = [&](const std::string& size) {
        const std::string model = (dir / ("t" + size + ".obj")).string();
        write_file(model, "v 0 0 0\nv " + size + " 0 0\nv 0 " + size + " 0\nf 1 2 3\n");
        auto r = run_stipple({"render", model, "-o", (dir / ("t" + size + ".png")).string(), "--width", "320", "--height",
                              "256", "--stats"});
        EXPECT_EQ(r.exit_code, 0) << size << ": " << r.err;
        return drawn_stipples(r);
    };
    const long unit = drawn("1");
    ASSERT_GT(unit, 500);
    // Within 1%: the triangle is large on screen, so each stipple is drawn at the density where it lies (the facing
    // toward the eye changes across it), and the stipples generated at each size sit a little differently.
    for (const std::string size : {"1e-12", "1e-8", "1e10", "1e17"}) EXPECT_NEAR(drawn(size), unit, 0.01 * double(unit)) << size;
    // (The last: a unit triangle 1e7 units from the origin, whose corners single precision cannot tell apart.)
    for (const auto& [size, message] : {std::pair<std::string, std::string>{"1e19", "beyond the 1e+18 units"},
                                        {"1e-20", "units across, below the 1e-15"},
                                        {"far", "from the origin along an axis, 1e+07 times its size"}}) {
        const std::string model = (dir / ("t" + size + ".obj")).string();
        if (size == "far") write_file(model, "v 1e7 0 0\nv 10000001 0 0\nv 1e7 1 0\nf 1 2 3\n");
        else write_file(model, "v 0 0 0\nv " + size + " 0 0\nv 0 " + size + " 0\nf 1 2 3\n");
        auto r = run_stipple({"render", model, "-o", (dir / "refused.png").string()});
        EXPECT_NE(r.exit_code, 0) << size;
        EXPECT_EQ(count_lines(r.err), 1u) << r.err;
        EXPECT_NE(r.err.find(model), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    }
}

// The light is a direction: its length does not matter, however large or small (its squared length in
// float overflowed at 1e20 and vanished at 1e-15).
TEST(CliRender, TheLightIsADirectionOfAnyLength) {
    const std::filesystem::path dir = test::temp_dir("cli-light");
    auto drawn = [&](const std::string& light) {
        auto r = run_stipple({"render", "-o", (dir / "l.png").string(), "--width", "160", "--height", "128", "--light",
                              light, "--stats"});
        EXPECT_EQ(r.exit_code, 0) << light << ": " << r.err;
        return drawn_stipples(r);
    };
    const long unit = drawn("1,2,3");
    EXPECT_GT(unit, 100);
    EXPECT_EQ(drawn("1e20,2e20,3e20"), unit);
    EXPECT_EQ(drawn("1e-15,2e-15,3e-15"), unit);
    EXPECT_NE(drawn("3,2,1"), unit) << "another direction should draw other stipples";
}

TEST(CliRender, StatsPrintTheDepthPassTriangles) {
    const std::filesystem::path dir = test::temp_dir("cli-depth-cull");
    auto depth_line = [&](const std::string& mode) {
        auto r = run_stipple({"render", "-o", (dir / (mode + ".png")).string(), "--width", "320", "--height", "256",
                              "--distance", "6", "--depth-cull", mode, "--depth-raster", "fixed", "--stats"});
        EXPECT_EQ(r.exit_code, 0) << r.err;
        const size_t at = r.out.find("depth pass:");
        return at == std::string::npos ? std::string() : r.out.substr(at, r.out.find('\n', at) - at);
    };
    const std::string off = depth_line("off"), on = depth_line("on");
    EXPECT_NE(off.find("(100.0%; --depth-cull off)"), std::string::npos) << off;
    ASSERT_NE(on.find("--depth-cull on"), std::string::npos) << on;
    const double percent = std::stod(on.substr(on.find('(') + 1));
    EXPECT_LT(percent, 60.0) << on;
    EXPECT_GT(percent, 0.0) << on;
    // By compute (the default on a CPU device) there are no lists: --stats says which pass ran.
    auto r = run_stipple({"render", "-o", (dir / "compute.png").string(), "--width", "320", "--height", "256",
                          "--depth-raster", "compute", "--stats"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("depth pass:         by compute (--depth-raster compute)"), std::string::npos) << r.out;
    // Compute asked, but a toon object needs the fixed-function pass: said so, not silently.
    auto toon = run_stipple({"render", "-o", (dir / "toon.png").string(), "--width", "320", "--height", "256",
                             "--depth-raster", "compute", "--toon", "--stats"});
    ASSERT_EQ(toon.exit_code, 0) << toon.err;
    EXPECT_NE(toon.out.find("; fixed, not compute: a toon object's shading needs the fixed-function pass"), std::string::npos)
        << toon.out;
    auto bad = run_stipple({"render", "-o", (dir / "bad.png").string(), "--depth-raster", "gpu"});
    EXPECT_NE(bad.exit_code, 0);
    EXPECT_NE(bad.err.find("--depth-raster = gpu must be auto, compute or fixed"), std::string::npos) << bad.err;
}

// --stats' ink is the tone as `tone` measures it: 1 - luminance over the covered pixels, grey ink included.
// It counted the pixels darker than half: a faint drawing's grey dots read as no ink (spot at --dmax 0.01:
// 0.1% for 1.08%), toon shading's grey as all ink (100%).
TEST(CliRender, StatsInkIsTheMeanInkOverTheCoveredPixels) {
    const std::filesystem::path dir = test::temp_dir("cli-stats-ink");
    for (const std::vector<std::string>& look : {std::vector<std::string>{"--dmax", "0.01"}, std::vector<std::string>{"--toon"}}) {
        std::vector<std::string> args = {"render", "-o", (dir / "ink.png").string(), "--mask", (dir / "mask.png").string(),
                                         "--width", "320", "--height", "256", "--stats"};
        args.insert(args.end(), look.begin(), look.end());
        const test::CommandResult r = run_stipple(args);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        const size_t at = r.out.find("mean ink inside:");
        ASSERT_NE(at, std::string::npos) << r.out;
        const double printed = std::stod(r.out.substr(at + std::strlen("mean ink inside:"))) / 100.0;
        const Image image = read_png((dir / "ink.png").string()), mask = read_png((dir / "mask.png").string());
        double ink = 0.0;
        size_t covered = 0;
        for (size_t i = 0; i < size_t(image.width) * size_t(image.height); ++i) {
            if (mask.pixels[size_t(mask.channels) * i] < 128) continue;
            ++covered;
            ink += 1.0 - image.pixels[size_t(image.channels) * i] / 255.0;
        }
        ASSERT_GT(covered, 1000u);
        std::printf("%s: --stats %.4f, the PNG's mean ink over its mask %.4f\n", look[0].c_str(), printed, ink / double(covered));
        EXPECT_NEAR(printed, ink / double(covered), 0.0001) << look[0];
        EXPECT_GT(printed, 0.0) << look[0];
        EXPECT_LT(printed, 0.9) << look[0];
    }
}

// --stats reads the ink from the paper's luminance toward the ink's: white ink on black paper is the same
// drawing as black on white (it read 1 - luminance, the black paper as three quarters ink), and where the
// two are of one luminance there is nothing to read.
TEST(CliRender, StatsInkIsReadBetweenThePaperAndTheInk) {
    const std::filesystem::path dir = test::temp_dir("cli-stats-colours");
    std::string err;  // the last command's
    auto ink_of = [&](const std::string& colours) {
        std::ofstream(dir / "scene.json") << R"({"objects": [{"model": ")" << test::source_path("assets/blobby.glb") << R"("}])" << colours << "}";
        const test::CommandResult r = run_stipple({"render", (dir / "scene.json").string(), "-o", (dir / "ink.png").string(), "--width",
                                                   "320", "--height", "256", "--stats"});
        EXPECT_EQ(r.exit_code, 0) << r.err;
        err = r.err;
        const size_t at = r.out.find("mean ink inside:");
        EXPECT_NE(at, std::string::npos) << r.out;
        return at == std::string::npos ? std::string() : r.out.substr(at, r.out.find('\n', at) - at);
    };
    const std::string black_on_white = ink_of(""), white_on_black = ink_of(R"(, "paper": [0, 0, 0], "ink": [1, 1, 1])");
    EXPECT_EQ(err, "");
    const std::string grey = ink_of(R"(, "paper": [0.5, 0.5, 0.5], "ink": [0.5, 0.5, 0.5])");
    // And the render says so, once (a sci-vis walkthrough's black ink on black paper drew a plain image without a word).
    EXPECT_NE(err.find("the paper and the ink are the same colour: the drawing will not show"), std::string::npos) << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    std::printf("%s\n%s\n%s\n", black_on_white.c_str(), white_on_black.c_str(), grey.c_str());
    const double a = std::stod(black_on_white.substr(std::strlen("mean ink inside:"))), b = std::stod(white_on_black.substr(std::strlen("mean ink inside:")));
    EXPECT_GT(a, 5.0);
    EXPECT_NEAR(b, a, 0.02 * a);
    EXPECT_NE(grey.find("not measured"), std::string::npos) << grey;
    // Light ink on dark paper as SVG: the page is left unpainted unless --fill-paper, so white paper would show.
    std::ofstream(dir / "dark.json") << R"({"objects": [{"model": ")" << test::source_path("assets/blobby.glb")
                                     << R"("}], "paper": [0.1, 0.1, 0.15], "ink": [0.95, 0.95, 0.9]})";
    for (const bool painted : {false, true}) {
        std::vector<std::string> args = {"render", (dir / "dark.json").string(), "-o", (dir / "dark.svg").string(), "--width", "160", "--height", "128"};
        if (painted) args.push_back("--fill-paper");
        const test::CommandResult r = run_stipple(args);
        EXPECT_EQ(r.exit_code, 0) << r.err;
        EXPECT_EQ(r.err.find("the ink is lighter than the paper") != std::string::npos, !painted) << r.err;
    }
}

// --ink and --paper colour the image (#rrggbb, #rgb, or R,G,B): the background is the paper, every inked pixel
// a mix of the paper and the ink; with a scene file they replace the scene's colours.
TEST(CliRender, InkAndPaperOptionsColourTheImage) {
    const std::filesystem::path dir = test::temp_dir("cli-ink-paper");
    std::ofstream(dir / "scene.json") << R"({"objects": [{"model": ")" << test::source_path("assets/blobby.glb")
                                      << R"("}], "paper": [1, 1, 1], "ink": [0, 0, 0]})";
    const glm::vec3 paper(0.0f, 0.0f, 0.2f), ink(0.8f, 0.8f, 0.2f);  // 0,0,0.2 and #cc3 (#cccc33)
    for (const bool scene : {false, true}) {
        std::vector<std::string> args = {"render", "-o", (dir / "c.png").string(), "--mask", (dir / "m.png").string(),
                                         "--width", "320", "--height", "256", "--ink", "#cc3", "--paper", "0,0,0.2"};
        if (scene) args.insert(args.begin() + 1, (dir / "scene.json").string());
        const test::CommandResult r = run_stipple(args);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        const Image image = read_png((dir / "c.png").string()), mask = read_png((dir / "m.png").string());
        size_t background = 0, paper_background = 0, inked = 0, on_the_way = 0;
        for (size_t i = 0; i < size_t(image.width) * image.height; ++i) {
            const uint8_t* p = &image.pixels[size_t(image.channels) * i];
            const glm::vec3 c(p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f);
            if (mask.pixels[size_t(mask.channels) * i] == 0) {
                ++background;
                paper_background += glm::all(glm::lessThan(glm::abs(c - paper), glm::vec3(1.0f / 255.0f)));
                continue;
            }
            if (glm::all(glm::lessThan(glm::abs(c - paper), glm::vec3(0.02f)))) continue;  // bare paper
            ++inked;
            on_the_way += test::on_the_way(c, paper, ink);
        }
        EXPECT_GT(background, 10000u) << scene;
        EXPECT_EQ(paper_background, background) << scene;
        EXPECT_GT(inked, 3000u) << scene;
        EXPECT_EQ(on_the_way, inked) << scene;
    }
}

// §2.1/§2.3's orientation term is the projected area's own factor, N_z (stipple_formulas.h orientation_factor):
// an unlit plate keeps its tone as it turns away, so where one part passes in front of another no light band
// runs along its outline. With the ramp sin^2(pi N_z / 2) read until 2026-12-06 the plate drew 0.61 of its
// facing tone at 75 degrees and 0.23 at 85; now 0.92 and 0.83 (its foreshortened dots overlap more).
TEST(CliRender, APlateKeepsItsToneAsItTurnsAway) {
    const std::filesystem::path dir = test::temp_dir("cli-plate-turns");
    std::string obj;
    constexpr int n = 40;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) obj += "v " + std::to_string(double(i) / n - 0.5) + " " + std::to_string(double(j) / n - 0.5) + " 0\n";
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int a = j * (n + 1) + i + 1, b = a + 1, c = a + n + 1, d = c + 1;
            obj += "f " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(d) + "\nf " + std::to_string(a) +
                   " " + std::to_string(d) + " " + std::to_string(c) + "\n";
        }
    const std::string plate = test::write_file(dir / "plate.obj", obj);
    auto ink_at = [&](const std::string& yaw) {
        const test::CommandResult r = run_stipple({"render", plate, "-o", (dir / ("plate" + yaw + ".png")).string(), "--width",
                                                   "640", "--height", "512", "--yaw", yaw, "--no-shading", "--no-intrinsic", "--stats"});
        EXPECT_EQ(r.exit_code, 0) << r.err;
        const size_t at = r.out.find("mean ink inside:");
        return at == std::string::npos ? 0.0 : std::stod(r.out.substr(at + std::strlen("mean ink inside:"))) / 100.0;
    };
    const double facing = ink_at("0"), turned = ink_at("75"), edge_on = ink_at("85");
    std::printf("an unlit plate's mean ink: facing %.4f, at 75 degrees %.4f (%.2f), at 85 %.4f (%.2f)\n", facing, turned,
                turned / facing, edge_on, edge_on / facing);
    EXPECT_GT(facing, 0.3);
    EXPECT_GT(turned / facing, 0.85);
    EXPECT_LT(turned / facing, 1.05);
    EXPECT_GT(edge_on / facing, 0.7);
}

// A round dot (point size above 2.5) is the disc of the square's area: the tone does not fall where the dots
// turn round (spot at 640 x 512: 54.3% of ink at 2.5, 48.2% at 2.51 until 2026-12-05), and grows with the size.
TEST(CliRender, TheToneDoesNotFallWhereDotsTurnRound) {
    const std::filesystem::path dir = test::temp_dir("cli-round-dots");
    auto ink_at = [&](const std::string& size) {
        const test::CommandResult r = run_stipple({"render", "-o", (dir / "dots.png").string(), "--width", "320", "--height",
                                                   "256", "--point-size", size, "--stats"});
        EXPECT_EQ(r.exit_code, 0) << r.err;
        const size_t at = r.out.find("mean ink inside:");
        return at == std::string::npos ? 0.0 : std::stod(r.out.substr(at + std::strlen("mean ink inside:"))) / 100.0;
    };
    const double square = ink_at("2.5"), round = ink_at("2.51"), larger = ink_at("2.8");
    std::printf("mean ink: 2.5-px squares %.4f, 2.51-px round dots %.4f, 2.8-px %.4f\n", square, round, larger);
    EXPECT_GT(square, 0.05);
    // Equal areas; the shapes overlap a little differently, and a round polygon's last dot is smaller where a
    // square one is fainter.
    EXPECT_GT(round / square, 0.97);
    EXPECT_LT(round / square, 1.07);
    EXPECT_GT(larger, round);
}

// At a low D_max a polygon that cannot hold a whole stipple even fully dark is selected (regime (b)), however
// large on screen: every polygon drew a faint grey dot until 2026-12-05 (the default scene at --dmax 0.01:
// most inked pixels the lightest greys). The tone follows D_max either way.
TEST(CliRender, ALowDensityDrawsSparseWholeDotsNotAGreyHaze) {
    const std::filesystem::path dir = test::temp_dir("cli-low-density");
    auto render = [&](const std::string& dmax) {
        const std::string png = (dir / ("d" + dmax + ".png")).string(), mask = (dir / ("m" + dmax + ".png")).string();
        const test::CommandResult r =
            run_stipple({"render", "-o", png, "--mask", mask, "--width", "320", "--height", "256", "--dmax", dmax});
        EXPECT_EQ(r.exit_code, 0) << r.err;
        return std::pair{read_png(png), read_png(mask)};
    };
    struct Ink {
        double mean = 0.0;
        size_t inked = 0, whole = 0;  // pixels with any ink; of them, those at least half black
    };
    auto measure = [](const std::pair<Image, Image>& frame) {
        Ink ink;
        size_t covered = 0;
        const auto& [image, mask] = frame;
        for (size_t i = 0; i < size_t(image.width) * size_t(image.height); ++i) {
            if (mask.pixels[size_t(mask.channels) * i] < 128) continue;
            ++covered;
            const double dark = 1.0 - image.pixels[size_t(image.channels) * i] / 255.0;
            ink.mean += dark;
            ink.inked += dark > 0.02;
            ink.whole += dark >= 0.5;
        }
        ink.mean /= double(std::max<size_t>(covered, 1));
        return ink;
    };
    const Ink low = measure(render("0.01")), normal = measure(render("0.25"));
    std::printf("--dmax 0.01: mean ink %.4f, %zu inked pixels, %zu of them at least half black; --dmax 0.25: mean ink %.4f\n",
                low.mean, low.inked, low.whole, normal.mean);
    ASSERT_GT(low.inked, 20u);
    EXPECT_GT(double(low.whole), 0.97 * double(low.inked)) << "faint dots: a grey haze";
    EXPECT_NEAR(low.mean / normal.mean, 0.04, 0.012) << "the tone follows D_max";
}

// --repeat N --queued K times N batches of K frames recorded back to back (on a GPU the default is 8, on a
// CPU device 1): it says so, and the image it wrote is the one frame's.
TEST(CliRender, RepeatTimesQueuedFrames) {
    const std::filesystem::path dir = test::temp_dir("cli-queued");
    const std::string once = (dir / "once.png").string(), queued = (dir / "queued.png").string();
    auto a = run_stipple({"render", "-o", once, "--width", "320", "--height", "256", "--repeat", "2", "--silhouette-lines"});
    auto b = run_stipple({"render", "-o", queued, "--width", "320", "--height", "256", "--repeat", "2", "--queued", "3",
                          "--silhouette-lines"});
    ASSERT_EQ(a.exit_code, 0) << a.err;
    ASSERT_EQ(b.exit_code, 0) << b.err;
    EXPECT_NE(a.out.find("frames timed:       2 (after one warm-up frame)\n"), std::string::npos) << a.out;
    EXPECT_NE(b.out.find("each the wall time of 3 queued back to back over 3"), std::string::npos) << b.out;
    EXPECT_NE(b.out.find("gpu splat:"), std::string::npos) << b.out;
    EXPECT_EQ(read_png(once).pixels, read_png(queued).pixels);
}

// `stipple parity` compares two devices' drawings (issue 17); CI has one, compared with itself: the
// same stipples, a table row per view and path, and the verdict with exit status 0.
TEST(CliParity, ComparesADeviceWithItself) {
    const test::CommandResult r = run_stipple(
        {"parity", "--devices", "0,0", "--yaws", "2", "--paths", "splat,indirect", "--width", "160", "--height", "128"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("parity holds"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("| indirect | 180:-20 |"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("drawn counts 0.0000% apart"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace stipple
