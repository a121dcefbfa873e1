#include "isolated_run.h"

#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "ghoracle/peer.h"

namespace gh::experiments {
namespace {

// The child's report through a pipe: one status byte, then the message (refusal or exception)
// or the answer's rings as raw doubles. Both ends are this program, so no format is needed
// beyond the layout of the bytes.
enum : std::uint8_t { kAnswered = 1, kRefused = 2, kThrew = 3 };

void put(std::vector<char>& out, const void* p, std::size_t n) {
  out.insert(out.end(), static_cast<const char*>(p), static_cast<const char*>(p) + n);
}
void putU64(std::vector<char>& out, std::uint64_t v) { put(out, &v, sizeof v); }

std::vector<char> encodeMessage(std::uint8_t status, const std::string& message) {
  std::vector<char> out{static_cast<char>(status)};
  putU64(out, message.size());
  put(out, message.data(), message.size());
  return out;
}

std::vector<char> encodeAnswer(const Region& r) {
  std::vector<char> out{static_cast<char>(kAnswered)};
  putU64(out, r.size());
  for (const Ring& ring : r) {
    putU64(out, ring.size());
    put(out, ring.data(), ring.size() * sizeof(Point));
  }
  return out;
}

struct Reader {
  const std::vector<char>& in;
  std::size_t at = 1;
  void get(void* p, std::size_t n) {
    if (in.size() - at < n) throw std::runtime_error("truncated report from the child");
    std::memcpy(p, in.data() + at, n);
    at += n;
  }
  std::uint64_t u64() {
    std::uint64_t v;
    get(&v, sizeof v);
    return v;
  }
};

void writeAll(int fd, const std::vector<char>& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t k = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return;
    done += static_cast<std::size_t>(k);
  }
}

[[noreturn]] void child(int fd, const Method& method, const Region& subject, const Region& clip, Op op,
                        const IsolationLimits& limits) {
  const rlimit as{limits.addressSpaceBytes, limits.addressSpaceBytes};
  ::setrlimit(RLIMIT_AS, &as);
  std::vector<char> report;
  try {
    report = encodeAnswer(method.clip(subject, clip, op));
  } catch (const peers::PeerRefusal& e) {
    report = encodeMessage(kRefused, e.what());
  } catch (const std::exception& e) {
    report = encodeMessage(kThrew, e.what());
  } catch (...) {
    report = encodeMessage(kThrew, "unknown exception");
  }
  writeAll(fd, report);
  ::_exit(0);  // no atexit handlers, no flushing of the parent's buffers
}

}  // namespace

IsolatedRun runIsolated(const Method& method, const Region& subject, const Region& clip, Op op,
                        const IsolationLimits& limits) {
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
  if (pid == 0) {
    ::close(fds[0]);
    child(fds[1], method, subject, clip, op, limits);
  }
  ::close(fds[1]);

  std::vector<char> bytes;
  bool timedOut = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(limits.seconds);
  char buffer[1 << 16];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      timedOut = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(left.count()));
    if (ready < 0 && errno == EINTR) continue;
    if (ready == 0) {
      timedOut = true;
      break;
    }
    const ssize_t k = ::read(fds[0], buffer, sizeof buffer);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) break;  // end of the report (or an error: judged by the exit status below)
    bytes.insert(bytes.end(), buffer, buffer + k);
  }
  ::close(fds[0]);
  if (timedOut) ::kill(pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }

  IsolatedRun run;
  if (timedOut) {
    run.status = IsolatedRun::Status::TimedOut;
    run.message = "no answer within " + std::to_string(limits.seconds) + " s";
    return run;
  }
  if (WIFSIGNALED(status)) {
    run.status = IsolatedRun::Status::Crashed;
    run.message = std::string("killed by signal ") + std::to_string(WTERMSIG(status)) + " (" + ::strsignal(WTERMSIG(status)) + ")";
    return run;
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || bytes.empty()) {
    run.status = IsolatedRun::Status::Crashed;
    run.message = "exited with status " + std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + " without an answer";
    return run;
  }
  Reader r{bytes};
  if (bytes[0] == kAnswered) {
    run.status = IsolatedRun::Status::Answered;
    run.result.resize(r.u64());
    for (Ring& ring : run.result) {
      ring.resize(r.u64());
      r.get(ring.data(), ring.size() * sizeof(Point));
    }
  } else {
    run.status = bytes[0] == kRefused ? IsolatedRun::Status::Refused : IsolatedRun::Status::Threw;
    run.message.resize(r.u64());
    r.get(run.message.data(), run.message.size());
  }
  return run;
}

}  // namespace gh::experiments
