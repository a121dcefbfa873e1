// Writing a tool's output files as a user expects: all of them or none.
//
// A regular file (or a new one) is written to a temporary file beside it and renamed over it, so
// a failure leaves the old file or nothing, never half an answer; through a symbolic link, the
// link's target is replaced and the link stays. FIFOs, character devices and "-" (standard
// output) are written directly: they cannot be replaced, and replacing /dev/null with a regular
// file (as a rename would, as root) breaks the machine. Every error (full disk, unwritable
// directory, a directory as the path) throws WriteError naming the path; the temporary files of
// the set are removed.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace gh::io {

class WriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class OutputFiles {
 public:
  // Text for path ("-": standard output); written by commit(), with a final newline.
  void add(std::string path, std::string text);
  // Writes every file: first each regular file's temporary, then the direct outputs, then the
  // renames. Throws WriteError (and leaves no temporary) on the first failure.
  void commit();

 private:
  struct Output {
    std::string path, text;
  };
  std::vector<Output> outputs_;
};

// One file the same way.
void writeText(const std::string& path, const std::string& text);

}  // namespace gh::io
