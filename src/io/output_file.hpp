#pragma once
// Whether a file can be written at a path, asked before the work that makes it: a render of a large model
// takes minutes to generate and draw, and an output that cannot be written was named only then.
#include <cstdio>
#include <functional>
#include <string>
#include <string_view>

namespace stipple {

// Throws a one-line error naming `path` (as `option` gave it, e.g. "-o") when no file can be written there:
// a folder of that name, a parent that is a file, a place where files cannot be made (/proc, a read-only
// disk, a folder without permission), an existing file without write permission. Makes no folder (the writers
// make the missing ones): the nearest existing one is tried. Never opens the output itself: an existing file, pipe or link is left as it is, and a
// new file's folder is tried with a temporary file of another name.
void check_output_writable(const std::string& option, const std::string& path);

// Writes an output file (an image, a drawing) whole or not at all: `write(out)` writes it to `out`, a new
// file beside `path` (a name of its own, made without following links, with the old file's mode), flushed to
// the disk and then renamed over `path`. A write that fails (a full disk, the file-size limit, an error in the
// writer) or is interrupted (SIGINT, SIGTERM, SIGHUP) removes that file and leaves whatever was at `path`
// before: it had left a truncated file in place of the good one. Written in place, as before, where `path` is
// a link, a pipe or a device, a file with other hard links or of another owner, or where the new file cannot
// be made or renamed there (a folder that takes no new file, a sticky one). Messages name `path`, prefixed by
// `what` ("cannot write PNG"). Makes the missing folders.
void write_output(const std::string& path, const std::string& what, const std::function<void(std::FILE* out)>& write);
// The same for bytes in memory.
void write_output(const std::string& path, const std::string& what, std::string_view bytes);

}  // namespace stipple
