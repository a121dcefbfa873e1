#include "ghio/output_files.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <iostream>
#include <sys/stat.h>
#include <unistd.h>

namespace gh::io {
namespace {

[[noreturn]] void fail(const std::string& path, int error) {
  throw WriteError("cannot write " + (path == "-" ? std::string("standard output") : path) + ": " +
                   std::strerror(error));
}

void writeAll(int fd, const std::string& path, const std::string& text) {
  const char* p = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail(path, errno);
    }
    p += n, left -= static_cast<std::size_t>(n);
  }
}

// A temporary file written beside a regular file's target, renamed over it on commit.
struct Staged {
  std::string path, target, temporary;
};


// Where a regular (or new) file's bytes go: the symbolic link's target, if path is a link.
std::string resolvedTarget(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_symlink(path, ec)) {
    const auto target = std::filesystem::canonical(path, ec);
    if (!ec) return target.string();
  }
  return path;
}

Staged stage(const std::string& path, const std::string& text) {
  const std::string target = resolvedTarget(path);
  const std::filesystem::path p(target);
  const std::filesystem::path dir = p.has_parent_path() ? p.parent_path() : std::filesystem::path(".");
  std::string temporary = (dir / ("." + p.filename().string() + ".ghclip-XXXXXX")).string();
  const int fd = ::mkstemp(temporary.data());
  if (fd < 0) fail(path, errno);
  try {
    // The mode a new file would get (mkstemp makes 0600), or the replaced file's.
    struct stat st {};
    mode_t mode;
    if (::stat(target.c_str(), &st) == 0) {
      mode = st.st_mode & 07777;
    } else {
      const mode_t mask = ::umask(0);
      ::umask(mask);
      mode = 0666 & ~mask;
    }
    if (::fchmod(fd, mode) != 0) fail(path, errno);
    writeAll(fd, path, text);
    writeAll(fd, path, "\n");
  } catch (...) {
    ::close(fd);
    ::unlink(temporary.c_str());
    throw;
  }
  if (::close(fd) != 0) {
    const int error = errno;
    ::unlink(temporary.c_str());
    fail(path, error);
  }
  return {path, target, temporary};
}

void writeDirect(const std::string& path, const std::string& text) {
  if (path == "-") {
    std::cout.flush();
    writeAll(STDOUT_FILENO, path, text);
    writeAll(STDOUT_FILENO, path, "\n");
    return;
  }
  const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) fail(path, errno);
  try {
    writeAll(fd, path, text);
    writeAll(fd, path, "\n");
  } catch (...) {
    ::close(fd);
    throw;
  }
  if (::close(fd) != 0) fail(path, errno);
}

// Written directly: standard output and anything that exists and is not a regular file.
bool isDirect(const std::string& path) {
  if (path == "-") return true;
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return false;  // new (or a dangling link): staged
  if (S_ISDIR(st.st_mode)) fail(path, EISDIR);
  return !S_ISREG(st.st_mode);
}

}  // namespace

void OutputFiles::add(std::string path, std::string text) { outputs_.push_back({std::move(path), std::move(text)}); }

void OutputFiles::commit() {
  std::vector<Staged> staged;
  auto removeStaged = [&] {
    for (const Staged& s : staged) ::unlink(s.temporary.c_str());
  };
  try {
    std::vector<const Output*> direct;
    for (const Output& o : outputs_) {
      if (isDirect(o.path)) {
        direct.push_back(&o);
      } else {
        staged.push_back(stage(o.path, o.text));
      }
    }
    for (const Output* o : direct) writeDirect(o->path, o->text);
    for (std::size_t i = 0; i < staged.size(); ++i) {
      if (::rename(staged[i].temporary.c_str(), staged[i].target.c_str()) != 0) {
        const int error = errno;
        const std::string path = staged[i].path;
        staged.erase(staged.begin(), staged.begin() + static_cast<std::ptrdiff_t>(i));  // renamed already
        fail(path, error);
      }
    }
  } catch (...) {
    removeStaged();
    throw;
  }
  outputs_.clear();
}

void writeText(const std::string& path, const std::string& text) {
  OutputFiles files;
  files.add(path, text);
  files.commit();
}

}  // namespace gh::io
