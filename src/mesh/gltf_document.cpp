#include "mesh/gltf_document.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "mesh/gltf_draco.hpp"
#include "mesh/gltf_meshopt.hpp"
#include "mesh/glb_container.hpp"
#include "mesh/gltf_validate.hpp"
#include "mesh/loader_util.hpp"

namespace stipple {

namespace {

// Images play no part in stippling: skip decoding any left (and any failure to).
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
    return true;
}

// Bytes from memory have no folder: a reference to an external file is refused, not looked up in
// the current directory.
bool no_external_file(std::vector<unsigned char>*, std::string* err, const std::string& uri, void*) {
    if (err) *err = "external file '" + uri + "' cannot be read: the model was not loaded from a file";
    return false;
}
bool no_file_exists(const std::string&, void*) { return false; }
std::string unexpanded(const std::string& path, void*) { return path; }
bool no_file_written(std::string*, const std::string&, const std::vector<unsigned char>&, void*) { return false; }

// External buffers are read here, not by tinygltf: it would resolve their names its own way ('+' read as a
// space, an absolute path joined to the folder, then looked up in the current directory) and read a file
// whole before comparing its size with byteLength. Each one's uri is replaced with a name of ours that the
// file callbacks below serve from these bytes; nothing else is opened.
struct ExternalBuffers {
    std::map<std::string, std::vector<unsigned char>> by_name;
};

std::string served_name(size_t buffer) { return "stipple-external-buffer-" + std::to_string(buffer); }

std::string last_component(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

bool external_buffer_exists(const std::string& path, void* user) {
    return static_cast<ExternalBuffers*>(user)->by_name.count(last_component(path)) > 0;
}

bool read_external_buffer(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
    auto& buffers = static_cast<ExternalBuffers*>(user)->by_name;
    const auto found = buffers.find(last_component(path));
    if (found == buffers.end()) {
        if (err) *err = "not an external buffer of this model";
        return false;
    }
    *out = std::move(found->second);
    return true;
}

// The first byteLength bytes of the file (the validator checked that it holds them; a longer file is read
// only as far as the buffer goes).
std::vector<unsigned char> read_buffer_file(const std::string& model, const std::string& where, const std::string& uri,
                                            const std::filesystem::path& file, uint64_t length) {
    const std::string named = where + ".uri: " + quoted_excerpt(uri, 64);
    struct Descriptor {
        int fd;
        ~Descriptor() { if (fd >= 0) ::close(fd); }
    } file_descriptor{::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};  // no wait on a FIFO
    const int fd = file_descriptor.fd;
    if (fd < 0) fail_file(model, named + " cannot be read: " + std::strerror(errno));
    struct stat info {};
    if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode) || uint64_t(info.st_size) < length)
        fail_file(model, named + " is not a regular file of at least " + std::to_string(length) + " bytes");
    std::vector<unsigned char> bytes(length);
    size_t done = 0;
    while (done < length) {
        const ssize_t got = ::read(fd, bytes.data() + done, length - done);
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) fail_file(model, named + " cannot be read: " + (got < 0 ? std::strerror(errno) : "the file ended early"));
        done += size_t(got);
    }
    return bytes;
}

// Takes every external buffer out of `doc` into `buffers`; true when the document changed.
bool take_external_buffers(const std::string& model, nlohmann::json& doc, const std::filesystem::path& base_dir,
                           ExternalBuffers& buffers, uint64_t document_bytes) {
    const auto list = doc.find("buffers");
    if (list == doc.end() || !list->is_array()) return false;
    bool changed = false;
    // The files are read whole, and the mesh made from them takes as much again: together they may be at most
    // half the machine's memory, as a model file may (check_model_size; the .gltf's own size said nothing of
    // its buffers, and a huge one ran out of memory reported with the .gltf's size).
    const uint64_t memory = physical_memory_bytes();
    uint64_t external = document_bytes;  // the .gltf or .glb itself (its data: URIs, its BIN chunk) counts too
    for (size_t i = 0; i < list->size(); ++i) {
        nlohmann::json& buffer = (*list)[i];
        const auto uri = buffer.find("uri");
        if (uri == buffer.end() || !uri->is_string()) continue;
        const std::string text = uri->get<std::string>();
        if (text.rfind("data:", 0) == 0) continue;
        const uint64_t length = buffer.at("byteLength").get<uint64_t>();
        external += length;
        if (memory > 0 && external > memory / 2)
            fail_file(model, "buffers[" + std::to_string(i) + "].uri: " + quoted_excerpt(text, 64) + " takes the model's files to " +
                                 byte_size(external) + ", more than a model's files may be on this machine: " + byte_size(memory / 2) +
                                 ", half its " + byte_size(memory) + " of memory");
        const std::string name = served_name(i);
        buffers.by_name[name] =
            read_buffer_file(model, "buffers[" + std::to_string(i) + "]", text, external_buffer_path(base_dir, text), length);
        *uri = name;
        changed = true;
    }
    return changed;
}

// tinygltf's message, on one line and short: a data: URI it failed to decode is quoted whole (megabytes).
std::string tinygltf_message(const std::string& text) { return excerpt(text, 300); }

}  // namespace

tinygltf::Model read_gltf_model(const std::string& path, std::string_view bytes, const std::filesystem::path* base_dir,
                                std::string* decoded) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const bool binary = ext == ".glb";
    if (bytes.size() > UINT32_MAX) fail_file(path, "a glTF file of 4 GiB or more is not supported");
    nlohmann::json doc = validate_gltf(path, bytes, binary, base_dir);

    // Placeholder buffers of EXT_meshopt_compression, and Draco primitives' indices, get data tinygltf can
    // load: the file goes to it rewritten.
    const MeshoptPlan meshopt = prepare_meshopt(doc, binary);
    const bool draco_stand_ins = prepare_draco(doc);
    // Images play no part in stippling, and tinygltf would open and read every image file (a FIFO waited for
    // ever, a directory read as 2^63 bytes): images named by a uri are left out of what it parses. (Images in
    // buffer views, as a textured .glb holds them, open nothing: dropping them would copy the BIN chunk.)
    bool images_named = false;
    if (const auto images = doc.find("images"); images != doc.end() && images->is_array())
        for (const nlohmann::json& image : *images) images_named = images_named || (image.is_object() && image.contains("uri"));
    const bool images_dropped = images_named && doc.erase("images") > 0;
    ExternalBuffers external;
    const bool buffers_taken = base_dir && take_external_buffers(path, doc, *base_dir, external, bytes.size());
    std::string rewritten;
    if (!meshopt.placeholders.empty() || draco_stand_ins || images_dropped || buffers_taken) {
        rewritten = binary ? join_glb(doc.dump(), split_glb(path, bytes).bin) : doc.dump();
        if (rewritten.size() > UINT32_MAX) fail_file(path, "a glTF file of 4 GiB or more is not supported");
        bytes = rewritten;
    }

    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&skip_image, nullptr);
    if (base_dir)
        loader.SetFsCallbacks({&external_buffer_exists, &unexpanded, &read_external_buffer, &no_file_written, &external});
    else
        loader.SetFsCallbacks({&no_file_exists, &unexpanded, &no_external_file, &no_file_written, nullptr});
    const std::string dir = base_dir ? base_dir->string() : std::string();
    tinygltf::Model model;
    std::string err, warn;
    const auto size = static_cast<unsigned int>(bytes.size());
    const bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()), size, dir)
                           : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), size, dir);
    if (!ok) fail_file(path, "cannot read glTF: " + tinygltf_message(err.empty() ? warn : err));
    if (!warn.empty()) std::fprintf(stderr, "%s: warning: %s\n", path.c_str(), tinygltf_message(warn).c_str());
    if (!meshopt.empty()) decode_meshopt(path, meshopt, model);
    const size_t draco_primitives = decode_draco(path, model);
    if (decoded) {
        auto count = [](size_t n, const char* one) { return std::to_string(n) + " " + one + (n == 1 ? "" : "s"); };
        std::vector<std::string> parts;
        if (!meshopt.views.empty()) parts.push_back("EXT_meshopt_compression (" + count(meshopt.views.size(), "buffer view") + ")");
        if (draco_primitives) parts.push_back("KHR_draco_mesh_compression (" + count(draco_primitives, "primitive") + ")");
        const auto used = doc.find("extensionsUsed");
        if (used != doc.end() && used->is_array())
            for (const nlohmann::json& e : *used)
                if (e == "KHR_mesh_quantization") parts.push_back("KHR_mesh_quantization");
        decoded->clear();
        for (const std::string& part : parts) *decoded += (decoded->empty() ? "" : ", ") + part;
    }
    return model;
}

}  // namespace stipple
