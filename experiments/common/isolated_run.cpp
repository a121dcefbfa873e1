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

#include "ghpeers/peer.h"

namespace gh::experiments {
namespace {

// Messages through the pipes are a length (u64) and that many bytes. Both ends are this program,
// so no format is needed beyond the layout of the bytes:
//   request:  method (u64), op (u8), subject, clip
//   response: status (u8), then the message (refusal, exception) or the answer
//   region:   ring count (u64), then per ring its point count (u64) and points as raw doubles
enum : std::uint8_t { kAnswered = 1, kRefused = 2, kThrew = 3 };

struct Writer {
  std::vector<char> bytes;
  void put(const void* p, std::size_t n) {
    bytes.insert(bytes.end(), static_cast<const char*>(p), static_cast<const char*>(p) + n);
  }
  void u64(std::uint64_t v) { put(&v, sizeof v); }
  void u8(std::uint8_t v) { put(&v, 1); }
  void text(const std::string& s) { u64(s.size()), put(s.data(), s.size()); }
  void region(const Region& r) {
    u64(r.size());
    for (const Ring& ring : r) u64(ring.size()), put(ring.data(), ring.size() * sizeof(Point));
  }
};

struct Reader {
  const std::vector<char>& bytes;
  std::size_t at = 0;
  void get(void* p, std::size_t n) {
    if (bytes.size() - at < n) throw std::runtime_error("truncated message between runner and worker");
    std::memcpy(p, bytes.data() + at, n);
    at += n;
  }
  std::uint64_t u64() {
    std::uint64_t v;
    get(&v, sizeof v);
    return v;
  }
  std::uint8_t u8() {
    std::uint8_t v;
    get(&v, 1);
    return v;
  }
  std::string text() {
    std::string s(u64(), '\0');
    get(s.data(), s.size());
    return s;
  }
  Region region() {
    Region r(u64());
    for (Ring& ring : r) {
      ring.resize(u64());
      get(ring.data(), ring.size() * sizeof(Point));
    }
    return r;
  }
};

// Repeats a blocking ::read or ::write until all n bytes are moved; false at end of file or on
// an error other than an interrupted call.
template <typename Byte, typename Transfer>
bool transferAll(int fd, Byte* p, std::size_t n, Transfer transfer) {
  while (n > 0) {
    const ssize_t k = transfer(fd, p, n);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return false;
    p += k, n -= static_cast<std::size_t>(k);
  }
  return true;
}

bool writeAll(int fd, const void* data, std::size_t n) {
  return transferAll(fd, static_cast<const char*>(data), n, ::write);
}

bool sendMessage(int fd, const std::vector<char>& bytes) {
  const std::uint64_t n = bytes.size();
  return writeAll(fd, &n, sizeof n) && writeAll(fd, bytes.data(), bytes.size());
}

// Blocking read of exactly n bytes (the worker's side); false at end of file.
bool readAll(int fd, void* data, std::size_t n) { return transferAll(fd, static_cast<char*>(data), n, ::read); }

enum class Receive { Done, Closed, TimedOut };

// Reads exactly n bytes before the deadline (the runner's side).
Receive readBefore(int fd, char* p, std::size_t n, std::chrono::steady_clock::time_point deadline) {
  while (n > 0) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return Receive::TimedOut;
    pollfd pfd{fd, POLLIN, 0};
    const int ready = ::poll(&pfd, 1, static_cast<int>(left.count()));
    if (ready < 0 && errno == EINTR) continue;
    if (ready == 0) return Receive::TimedOut;
    const ssize_t k = ::read(fd, p, n);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return Receive::Closed;
    p += k, n -= static_cast<std::size_t>(k);
  }
  return Receive::Done;
}

}  // namespace

IsolatedRunner::IsolatedRunner(std::vector<Method> methods, IsolationLimits limits)
    : methods_(std::move(methods)), limits_(limits) {
  ::signal(SIGPIPE, SIG_IGN);  // a dead worker shows up as a failed write, not a dead runner
}

IsolatedRunner::~IsolatedRunner() { stop(false); }

void IsolatedRunner::start() {
  int request[2], response[2];
  if (::pipe(request) != 0 || ::pipe(response) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
  if (pid == 0) {
    ::close(request[1]);
    ::close(response[0]);
    serve(request[0], response[1]);
  }
  ::close(request[0]);
  ::close(response[1]);
  pid_ = pid;
  toWorker_ = request[1];
  fromWorker_ = response[0];
  served_ = 0;
}

// Closing the request pipe ends a healthy worker; kill ends a hung one.
void IsolatedRunner::stop(bool kill) {
  if (pid_ < 0) return;
  if (kill) ::kill(pid_, SIGKILL);
  ::close(toWorker_);
  ::close(fromWorker_);
  int status;
  while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  pid_ = -1;
}

void IsolatedRunner::serve(int in, int out) {
  const rlimit as{limits_.addressSpaceBytes, limits_.addressSpaceBytes};
  ::setrlimit(RLIMIT_AS, &as);
  for (;;) {
    std::uint64_t n;
    if (!readAll(in, &n, sizeof n)) ::_exit(0);
    std::vector<char> request(n);
    if (!readAll(in, request.data(), n)) ::_exit(0);
    Writer response;
    try {
      Reader r{request};
      const std::size_t method = r.u64();
      const Op op = static_cast<Op>(r.u8());
      const Region subject = r.region(), clip = r.region();
      const Region answer = methods_.at(method).clip(subject, clip, op);
      response.u8(kAnswered);
      response.region(answer);
    } catch (const peers::PeerRefusal& e) {
      response = {};
      response.u8(kRefused), response.text(e.what());
    } catch (const std::exception& e) {
      response = {};
      response.u8(kThrew), response.text(e.what());
    } catch (...) {
      response = {};
      response.u8(kThrew), response.text("unknown exception");
    }
    if (!sendMessage(out, response.bytes)) ::_exit(0);
  }
}

IsolatedRun IsolatedRunner::run(std::size_t method, const Region& subject, const Region& clip, Op op) {
  if (pid_ >= 0 && served_ >= kCasesPerWorker) stop(false);
  if (pid_ < 0) start();
  ++served_;
  Writer request;
  request.u64(method);
  request.u8(static_cast<std::uint8_t>(op));
  request.region(subject);
  request.region(clip);

  IsolatedRun run;
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(limits_.seconds));
  std::uint64_t n = 0;
  std::vector<char> response;
  Receive got = sendMessage(toWorker_, request.bytes) ? readBefore(fromWorker_, reinterpret_cast<char*>(&n), sizeof n, deadline)
                                                      : Receive::Closed;
  if (got == Receive::Done) {
    response.resize(n);
    got = readBefore(fromWorker_, response.data(), n, deadline);
  }
  if (got == Receive::TimedOut) {
    stop(true);
    run.status = IsolatedRun::Status::TimedOut;
    run.message = "no answer within " + std::to_string(limits_.seconds) + " s";
    return run;
  }
  if (got == Receive::Closed) {
    // The worker died on this case: say how.
    ::close(toWorker_);
    ::close(fromWorker_);
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    pid_ = -1;
    run.status = IsolatedRun::Status::Crashed;
    run.message = WIFSIGNALED(status) ? std::string("killed by signal ") + std::to_string(WTERMSIG(status)) + " (" +
                                            ::strsignal(WTERMSIG(status)) + ")"
                                      : "exited with status " + std::to_string(WEXITSTATUS(status));
    return run;
  }
  Reader r{response};
  const std::uint8_t status = r.u8();
  if (status == kAnswered) {
    run.status = IsolatedRun::Status::Answered;
    run.result = r.region();
  } else {
    run.status = status == kRefused ? IsolatedRun::Status::Refused : IsolatedRun::Status::Threw;
    run.message = r.text();
  }
  return run;
}

}  // namespace gh::experiments
