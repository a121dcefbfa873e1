// A peer library run in a child process, so that its crash cannot take the tool down: the child
// clips and writes the answer (or the refusal, or the failure) to a pipe; a child that dies of
// a signal is reported as the peer's failure. (The robustness study isolates peers the same way,
// with worker processes and time limits: experiments/common/isolated_run.h.)
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstring>
#include <string>

#include "ghclip/errors.h"
#include "ghio/formats.h"
#include "ghpeers/peer.h"
#include "tool_main.h"

namespace gh::tools {

struct PeerOutcome {
  enum class Kind { Answered, Refused, Failed } kind = Kind::Failed;
  Region result;
  std::string message;  // the refusal or failure, one line
};

inline PeerOutcome clipInChild(const peers::Peer& peer, const Region& subject, const Region& clip, Op op) {
  int fds[2];
  if (::pipe(fds) != 0) return {PeerOutcome::Kind::Failed, {}, std::string("pipe: ") + std::strerror(errno)};
  std::fflush(nullptr);
  const pid_t child = ::fork();
  if (child < 0) return {PeerOutcome::Kind::Failed, {}, std::string("fork: ") + std::strerror(errno)};
  if (child == 0) {
    ::close(fds[0]);
    std::string text;
    try {
      text = "A" + io::writeWkt(peer.clip(subject, clip, op));
    } catch (const InvalidInput& e) {
      text = std::string("R") + e.what();
    } catch (const std::exception& e) {
      text = std::string("F") + e.what();
    }
    for (std::size_t done = 0; done < text.size();) {
      const ssize_t n = ::write(fds[1], text.data() + done, text.size() - done);
      if (n <= 0) ::_exit(3);
      done += static_cast<std::size_t>(n);
    }
    ::_exit(0);
  }
  ::close(fds[1]);
  std::string text;
  char buffer[1 << 16];
  for (ssize_t n; (n = ::read(fds[0], buffer, sizeof buffer)) != 0;) {
    if (n < 0) {
      if (errno == EINTR) continue;
      break;
    }
    text.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFSIGNALED(status)) {
    return {PeerOutcome::Kind::Failed, {}, std::string("crashed (") + ::strsignal(WTERMSIG(status)) + ")"};
  }
  if (text.empty() || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    return {PeerOutcome::Kind::Failed, {}, "its process ended without an answer"};
  }
  const std::string rest = oneLine(text.substr(1));
  if (text[0] == 'R') return {PeerOutcome::Kind::Refused, {}, rest};
  if (text[0] == 'F') return {PeerOutcome::Kind::Failed, {}, rest};
  Region result = io::readWkt(std::string_view(text).substr(1));
  for (Ring& ring : result) {
    if (ring.size() > 1 && ring.back() == ring.front()) ring.pop_back();  // WKT's closing point
  }
  return {PeerOutcome::Kind::Answered, std::move(result), ""};
}

}  // namespace gh::tools
