// The stipple cache's folder as a whole: listing, the size limit (least recently used first), clearing.
#include <algorithm>
#include <fstream>

#include "core/error.hpp"
#include "core/printf_string.hpp"
#include "stipple/cache_entry_format.hpp"
#include "stipple/stipple_cache.hpp"

namespace stipple {

namespace {

namespace fs = std::filesystem;

// Only files named as entry_path names them are ours: 16 lower-case hex digits (the key), then ".stipples",
// and for a writer's temporary file ".tmp<pid>-<time>" after that (finished or killed). A user's own
// "notes.stipples" in a shared folder is never listed, counted or removed.
constexpr size_t kKeyDigits = 16;
constexpr size_t kExtensionLength = sizeof(cache_format::kExtension) - 1;

bool starts_with_key_and_extension(const std::string& name) {
    if (name.size() < kKeyDigits + kExtensionLength) return false;
    for (size_t i = 0; i < kKeyDigits; ++i)
        if (!((name[i] >= '0' && name[i] <= '9') || (name[i] >= 'a' && name[i] <= 'f'))) return false;
    return name.compare(kKeyDigits, kExtensionLength, cache_format::kExtension) == 0;
}
bool is_entry(const fs::path& path) {
    const std::string name = path.filename().string();
    return name.size() == kKeyDigits + kExtensionLength && starts_with_key_and_extension(name);
}
bool is_temporary(const fs::path& path) {
    const std::string name = path.filename().string();
    return starts_with_key_and_extension(name) && name.compare(kKeyDigits + kExtensionLength, 4, ".tmp") == 0;
}

}  // namespace

// A folder that is not there is an empty cache; one that cannot be read is an error (it listed as empty
// and "cleared" with exit status 0).
fs::directory_iterator open_folder(const fs::path& dir) {
    std::error_code ec;
    fs::directory_iterator it(dir, ec);
    if (ec && ec != std::errc::no_such_file_or_directory)
        fail_file(dir.string(), "cannot read the stipple cache folder: " + ec.message());
    return it;
}

std::vector<CacheEntryInfo> list_cache_entries(const fs::path& dir) {
    std::vector<CacheEntryInfo> entries;
    std::error_code ec;
    for (const fs::directory_entry& file : open_folder(dir)) {
        if (!file.is_regular_file(ec) || !is_entry(file.path())) continue;
        CacheEntryInfo info;
        info.path = file.path();
        info.bytes = file.file_size(ec);
        info.last_used = file.last_write_time(ec);
        cache_format::Header header{};
        std::ifstream in(file.path(), std::ios::binary);
        if (in.read(reinterpret_cast<char*>(&header), sizeof(header)) && cache_format::header_valid(header)) {
            info.readable = true;
            info.triangles = header.triangles;
            info.stipples = header.stipples;
            info.model = header.model;
        }
        entries.push_back(info);
    }
    std::sort(entries.begin(), entries.end(),
              [](const CacheEntryInfo& a, const CacheEntryInfo& b) { return a.last_used > b.last_used; });
    return entries;
}

uint64_t enforce_cache_limit(const fs::path& dir, uint64_t max_bytes, const fs::path& keep) {
    struct File {
        fs::path path;
        uint64_t bytes;
        fs::file_time_type time;
    };
    std::vector<File> files;
    uint64_t total = 0, freed = 0;
    std::error_code ec;
    const auto now = fs::file_time_type::clock::now();
    for (const fs::directory_entry& file : fs::directory_iterator(dir, ec)) {
        if (!file.is_regular_file(ec)) continue;
        const bool temporary = is_temporary(file.path());
        if (!temporary && !is_entry(file.path())) continue;  // not ours: never touched
        const uint64_t bytes = file.file_size(ec);
        const auto time = file.last_write_time(ec);
        // A temporary file an hour old belongs to a killed process (a live writer renames within seconds).
        if (temporary && now - time > std::chrono::hours(1) && fs::remove(file.path(), ec)) {
            freed += bytes;
            continue;
        }
        total += bytes;
        if (!temporary && file.path() != keep) files.push_back({file.path(), bytes, time});
    }
    std::sort(files.begin(), files.end(), [](const File& a, const File& b) { return a.time < b.time; });
    for (const File& file : files) {
        if (total <= max_bytes) break;
        if (fs::remove(file.path, ec)) {  // another process may have removed it already
            total -= file.bytes;
            freed += file.bytes;
        }
    }
    return freed;
}

uint64_t clear_cache(const fs::path& dir) {
    uint64_t freed = 0;
    size_t kept = 0;
    std::string why;
    std::error_code ec;
    for (const fs::directory_entry& file : open_folder(dir)) {
        if (!file.is_regular_file(ec) || !(is_entry(file.path()) || is_temporary(file.path()))) continue;
        const uint64_t bytes = file.file_size(ec);
        std::error_code removing;
        if (fs::remove(file.path(), removing)) freed += bytes;
        else if (removing) ++kept, why = removing.message();  // (gone already: another process cleared it)
    }
    if (kept > 0)
        fail_file(dir.string(), "could not remove " + std::to_string(kept) + " cache entr" + (kept == 1 ? "y" : "ies") +
                                    " (" + why + "); " + printf_string("%.1f MiB", double(freed) / 1048576.0) + " freed");
    return freed;
}

}  // namespace stipple
