#pragma once
// All-or-nothing file output: the content is written to a temporary file in the target's
// directory, flushed, synced and renamed over the target. On any failure (including an exception
// thrown by the body) the temporary is removed and an existing target is left untouched.
#include <functional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace cmx::io {

using FileBody = std::function<void(std::ostream&)>;

// Calls body(stream) and commits its output to `path`. Throws IoError(write_failed) when the
// temporary cannot be created, written or renamed; rethrows exceptions of `body`.
void write_file_atomically(const std::string& path, const FileBody& body);

// Files that belong together (TetGen .node and .ele): every body is written to its temporary
// first, and only when all are complete are they renamed into place, in order. A failure while
// writing leaves every target untouched; only a failing rename (the temporaries are in the
// targets' directories, so this means the directory changed under us) can leave the files
// renamed before it updated.
void write_files_atomically(const std::vector<std::pair<std::string, FileBody>>& files);

}  // namespace cmx::io
