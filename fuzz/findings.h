// How fuzz targets report: trap() for findings that must stop a campaign (crashes of the exact
// variant's contract); record() for findings that are counted and written out (the naive and
// sweep variants' known weaknesses, a peer's disagreement), so a campaign goes on.
#pragma once

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <utility>

#include <fcntl.h>
#include <unistd.h>

#include "ghclip/operation.h"
#include "ghio/formats.h"

// The sanitizers' hook for their error reports; absent (null) in a build without them.
extern "C" void __sanitizer_set_death_callback(void (*callback)()) __attribute__((weak));

namespace gh::fuzz {

// The findings of this process, written out in blocks, not one file operation per finding: a
// campaign against the naive variant records more findings than it runs executions (212,236 in
// 120,906 at a66d06c), and opening, appending and closing two files for each cost a fifth of
// fuzz_clip_naive's executions (143 against 178 per second, one job, seed 3, its grown corpus).
// Lines are kept in order and flushed when the block is full, at exit, before a trap, and when a
// sanitizer reports (its death callback); a finding's input is written only while its cause and
// operation have been seen at most kInputsKept times in this process, as ./harness keeps the
// first kInputsKept of each for the report (any line among those first ones overall is among the
// first ones of its own process, whose lines stay in order).
class FindingLog {
 public:
  static constexpr int kInputsKept = 3;
  static constexpr std::size_t kBlock = std::size_t{1} << 16;

  static FindingLog& instance() {
    static FindingLog* log = [] {
      auto* made = new FindingLog();  // never destroyed: flushed by the handlers below
      std::atexit([] { instance().flush(); });
      if (__sanitizer_set_death_callback) __sanitizer_set_death_callback([] { instance().flush(); });
      return made;
    }();
    return *log;
  }

  bool enabled() const { return !path_.empty(); }
  const std::string& inputsDir() const { return inputsDir_; }

  // Whether the input of a finding with this cause and operation is to be written.
  bool keepInput(const std::string& cause, Op op) { return ++seen_[{cause, op}] <= kInputsKept; }

  void add(const std::string& line) {
    pending_ += line;
    if (pending_.size() >= kBlock) flush();
  }

  // One write(2) of whole lines to a file opened for appending: the kernel appends it in one
  // piece, so the jobs of a fork-mode campaign (processes appending to one file) never run into
  // each other's lines. stdio split a block into a write of its 4 KiB pages and one of the rest,
  // and another job's block could land between them (in the campaign at b82520d, twice in
  // 474,965 lines, and its report refused the cut lines).
  void flush() {
    if (pending_.empty() || path_.empty()) return;
    const int fd = ::open(path_.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
    if (fd >= 0) {
      const char* next = pending_.data();
      std::size_t left = pending_.size();
      while (left > 0) {  // a short write (a full disk, a signal) goes on where it stopped
        const ssize_t n = ::write(fd, next, left);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        next += n, left -= static_cast<std::size_t>(n);
      }
      ::close(fd);
    }
    pending_.clear();
  }

 private:
  FindingLog() {
    if (const char* p = std::getenv("GHCLIP_FUZZ_FINDINGS")) path_ = p;
    if (const char* d = std::getenv("GHCLIP_FUZZ_FINDINGS_INPUTS")) inputsDir_ = d;
  }
  std::string path_, inputsDir_, pending_;
  std::map<std::pair<std::string, Op>, int> seen_;
};

[[noreturn]] inline void trap(const std::string& what, const Region& s, const Region& c, Op op) {
  FindingLog::instance().flush();
  std::fprintf(stderr, "FINDING (trap): %s\n  op %s\n  subject %s\n  clip    %s\n", what.c_str(),
               std::string(name(op)).c_str(), io::writeWkt(s).c_str(), io::writeWkt(c).c_str());
  std::abort();
}

// The operands of one execution as its findings name them: their WKT written once, when the first
// finding asks for it. An execution records up to one finding per operation, and writing the WKT
// for each was 3 % of fuzz_clip_naive's time (perf). Made and dropped within the execution (text
// kept across executions would change their balance of allocations, which makes libFuzzer run an
// input again to look for a leak).
class RecordedOperands {
 public:
  RecordedOperands(const Region& subject, const Region& clip) : subject(subject), clip(clip) {}
  const Region& subject;
  const Region& clip;
  // "WKT(subject)\tWKT(clip)"
  const std::string& wkt() {
    if (wkt_.empty()) wkt_ = io::writeWkt(subject) + '\t' + io::writeWkt(clip);
    return wkt_;
  }

 private:
  std::string wkt_;
};

// One line per finding to $GHCLIP_FUZZ_FINDINGS (if set): target, what, op, WKT, WKT, and the
// name of the fuzz input, saved under $GHCLIP_FUZZ_FINDINGS_INPUTS (if set) for the first
// findings of each cause and operation, so that they can be replayed by their target and join
// the campaign's corpus. The cause is `what` up to a parenthesis (the figures after it vary).
inline void record(const char* target, const std::string& what, RecordedOperands& operands, Op op,
                   const std::uint8_t* data, std::size_t size) {
  FindingLog& log = FindingLog::instance();
  if (!log.enabled()) return;
  // FNV-1a of the input names it (distinct inputs, distinct names, for any practical campaign).
  std::uint64_t h = 1469598103934665603ull;
  for (std::size_t i = 0; i < size; ++i) h = (h ^ data[i]) * 1099511628211ull;
  char input[32];
  std::snprintf(input, sizeof input, "input-%016llx", static_cast<unsigned long long>(h));
  if (log.keepInput(what.substr(0, what.find(" (")), op) && !log.inputsDir().empty()) {
    if (std::FILE* f = std::fopen((log.inputsDir() + "/" + input).c_str(), "wb")) {
      std::fwrite(data, 1, size, f);
      std::fclose(f);
    }
  }
  log.add(std::string(target) + '\t' + what + '\t' + std::string(name(op)) + '\t' + operands.wkt() + '\t' + input +
          '\n');
}
inline void record(const char* target, const std::string& what, const Region& s, const Region& c, Op op,
                   const std::uint8_t* data, std::size_t size) {
  RecordedOperands operands(s, c);
  record(target, what, operands, op, data, size);
}

}  // namespace gh::fuzz
