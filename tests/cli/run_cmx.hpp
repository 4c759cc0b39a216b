#pragma once
// Runs a program (by default the cmx binary under test, CMX_EXE) with arguments and standard
// input, and returns its exit code, standard output and standard error. POSIX only; header-only
// so any test suite can include it.
//
//   auto r = cmx::test::run_cmx({"orient3d", "--filter", "exact"}, "0 0 0 1 0 0 0 1 0 0 0 1\n");
//   CHECK(r.exit_code == 0); CHECK(r.out == "+\n");
#include <fcntl.h>
#include <poll.h>
#include <stdlib.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "scratch.hpp"

namespace cmx::test {

struct RunResult {
  int exit_code = -1;  // the exit status, or 128 + signal number when killed by a signal
  std::string out, err;
};

// A pseudo-terminal for the child's stderr (programs show progress only on a terminal): fds[0]
// is the master the parent reads, fds[1] the terminal the child writes.
inline void open_terminal(int fds[2]) {
  fds[0] = posix_openpt(O_RDWR | O_NOCTTY);
  if (fds[0] < 0 || grantpt(fds[0]) || unlockpt(fds[0])) throw std::runtime_error("run_program: no pseudo-terminal");
  fds[1] = open(ptsname(fds[0]), O_RDWR | O_NOCTTY);
  if (fds[1] < 0) throw std::runtime_error("run_program: cannot open the pseudo-terminal");
}

// Runs `program` with `args` (argv[1..]), feeding `input` to its stdin; with
// `stderr_on_terminal`, stderr is a pseudo-terminal (err then holds what the terminal got).
// Throws std::runtime_error if the process cannot be started.
inline RunResult run_program(const std::string& program, const std::vector<std::string>& args,
                             const std::string& input = "", bool stderr_on_terminal = false) {
  int in_pipe[2], out_pipe[2], err_pipe[2];
  if (pipe(in_pipe) || pipe(out_pipe)) throw std::runtime_error("run_program: pipe failed");
  if (stderr_on_terminal) open_terminal(err_pipe);
  else if (pipe(err_pipe)) throw std::runtime_error("run_program: pipe failed");
  std::vector<char*> argv;
  argv.push_back(const_cast<char*>(program.c_str()));
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("run_program: fork failed");
  if (pid == 0) {  // child
    dup2(in_pipe[0], 0);
    dup2(out_pipe[1], 1);
    dup2(err_pipe[1], 2);
    for (int fd : {in_pipe[0], in_pipe[1], out_pipe[0], out_pipe[1], err_pipe[0], err_pipe[1]}) close(fd);
    execv(program.c_str(), argv.data());
    std::fprintf(stderr, "run_program: cannot execute %s\n", program.c_str());
    _exit(127);
  }
  close(in_pipe[0]);
  close(out_pipe[1]);
  close(err_pipe[1]);
  // Feed stdin and drain both outputs together, so no pipe fills up and blocks the child.
  signal(SIGPIPE, SIG_IGN);  // the child may exit without reading all of its input
  RunResult r;
  std::size_t written = 0;
  int to_child = in_pipe[1];
  if (input.empty()) {
    close(to_child);
    to_child = -1;
  }
  bool out_open = true, err_open = true;
  char buf[65536];
  while (out_open || err_open) {
    pollfd fds[3];
    int n = 0;
    if (out_open) fds[n++] = {out_pipe[0], POLLIN, 0};
    if (err_open) fds[n++] = {err_pipe[0], POLLIN, 0};
    if (to_child >= 0) fds[n++] = {to_child, POLLOUT, 0};
    if (poll(fds, nfds_t(n), -1) < 0) {
      if (errno == EINTR) continue;
      break;
    }
    for (int i = 0; i < n; ++i) {
      if (!fds[i].revents) continue;
      if (fds[i].fd == to_child) {
        const ssize_t w = write(to_child, input.data() + written, input.size() - written);
        if (w > 0) written += std::size_t(w);
        if (w < 0 || written == input.size()) {
          close(to_child);
          to_child = -1;
        }
        continue;
      }
      const ssize_t got = read(fds[i].fd, buf, sizeof buf);  // a terminal's master reads EIO at the end
      if (got > 0) {
        (fds[i].fd == out_pipe[0] ? r.out : r.err).append(buf, std::size_t(got));
      } else {
        if (fds[i].fd == out_pipe[0]) out_open = false;
        else err_open = false;
      }
    }
  }
  if (to_child >= 0) close(to_child);
  close(out_pipe[0]);
  close(err_pipe[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return r;
}

#ifdef CMX_EXE
// Runs the cmx binary built with the tests.
inline RunResult run_cmx(const std::vector<std::string>& args, const std::string& input = "") {
  return run_program(CMX_EXE, args, input);
}
#endif

// The bytes of a file ("" when it cannot be read).
inline std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Writes `content` to a fresh file in the process's scratch directory (scratch.hpp: removed at
// exit) and returns its path.
inline std::string write_temp_file(const std::string& content, const std::string& suffix = ".txt") {
  std::string pattern = (scratch_directory() / ("XXXXXX" + suffix)).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = mkstemps(name.data(), int(suffix.size()));
  if (fd < 0) throw std::runtime_error("write_temp_file: mkstemps failed");
  close(fd);
  std::ofstream(name.data(), std::ios::binary) << content;
  return name.data();
}

// A new empty directory in the process's scratch directory.
inline std::string fresh_directory() {
  const std::string path = write_temp_file("", "");
  std::filesystem::remove(path);
  std::filesystem::create_directories(path);
  return path;
}

}  // namespace cmx::test
