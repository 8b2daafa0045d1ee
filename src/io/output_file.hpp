#pragma once
// Whether a file can be written at a path, asked before the work that makes it: a render of a large model
// takes minutes to generate and draw, and an output that cannot be written was named only then.
#include <string>

namespace stipple {

// Throws a one-line error naming `path` (as `option` gave it, e.g. "-o") when no file can be written there:
// a folder of that name, a parent that is a file, a place where files cannot be made (/proc, a read-only
// disk, a folder without permission), an existing file without write permission. Makes no folder (the writers
// make the missing ones): the nearest existing one is tried. Never opens the output itself: an existing file, pipe or link is left as it is, and a
// new file's folder is tried with a temporary file of another name.
void check_output_writable(const std::string& option, const std::string& path);

}  // namespace stipple
