#pragma once
// All-or-nothing file output: the content is written to a temporary file in the target's
// directory, flushed, synced and renamed over the target. On any failure (including an exception
// thrown by the body) the temporary is removed and an existing target is left untouched.
#include <functional>
#include <ostream>
#include <string>

namespace cmx::io {

// Calls body(stream) and commits its output to `path`. Throws IoError(write_failed) when the
// temporary cannot be created, written or renamed; rethrows exceptions of `body`.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& body);

}  // namespace cmx::io
