#pragma once
// The files a command reads and writes, checked before it does any work: inputs readable,
// outputs writable, and no output that would overwrite an input or another output.
#include <string>
#include <vector>

namespace cmx::io {
class IoError;
}

namespace cmx::cli {

// "" when a file can be created at `path` (its directory exists and is writable), else why not.
std::string unwritable_reason(const std::string& path);

// The files a mesh path stands for: the path, and for TetGen's .node or .ele the other one too.
std::vector<std::string> mesh_files(const std::string& path);

// Throws Failure(exit 3) "PATH: is a directory" or "PATH: cannot open: REASON" (strerror) when
// the file cannot be read.
void check_readable(const std::string& path);

// True when a and b name one file: ./a.vtk and a.vtk, symbolic and hard links count.
bool same_file(const std::string& a, const std::string& b);

// Throws Failure(exit 2) when an output is one of the inputs or two outputs are one file.
void check_outputs_apart(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs);

// Throws Failure(exit 9) naming the first output that cannot be written.
void check_writable(const std::vector<std::string>& outputs);

// The exit code of an io error: 9 for a failed write, 4 for a mesh read but with inverted tets,
// 3 otherwise (unreadable or malformed).
int exit_code_of(const io::IoError& e);

}  // namespace cmx::cli
