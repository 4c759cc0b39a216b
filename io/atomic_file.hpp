#pragma once
// All-or-nothing file output: the content is written to a temporary file in the target's
// directory, flushed and renamed over the target. On any failure (including an exception thrown
// by the body) the temporary is removed and an existing target is left untouched: a reader, or a
// crash of the program, never sees a partial file. Surviving a power loss as well takes
// Durability::synced (fsync of every temporary before its rename and of the directory after),
// which costs every written file a disk round trip: about a millisecond each on the benchmark
// machine, the start-up budget of a tiny map (bench/results/map-local-repair.md).
#include <functional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace cmx::io {

using FileBody = std::function<void(std::ostream&)>;

enum class Durability {
  atomic,  // renamed into place, left to the operating system's write-back (the default)
  synced,  // fsync'ed before the rename, the directory fsync'ed after it
};
// Process-wide, for every later write (the program sets it once, from CMX_SYNC_OUTPUT).
void set_output_durability(Durability d);
Durability output_durability();

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
