// Runs methods on cases in a child process, so that a crash, a hang or a runaway allocation in a
// peer library ends that case only, never the experiment. One worker process serves case after
// case (forking per case costs more than most cases); it is replaced when it dies, hangs, or has
// served kCasesPerWorker cases (so leaks of one case cannot pile up into another's failure).
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

#include "methods.h"

namespace gh::experiments {

struct IsolatedRun {
  enum class Status { Answered, Refused, Threw, Crashed, TimedOut };
  Status status = Status::Threw;
  Region result;        // when Answered
  std::string message;  // refusal or exception text, or how the worker ended
};

struct IsolationLimits {
  double seconds = 20;                                // wall time per case before the worker is killed
  unsigned long long addressSpaceBytes = 8ull << 30;  // RLIMIT_AS of the worker
};

class IsolatedRunner {
 public:
  IsolatedRunner(std::vector<Method> methods, IsolationLimits limits);
  ~IsolatedRunner();
  IsolatedRunner(const IsolatedRunner&) = delete;
  IsolatedRunner& operator=(const IsolatedRunner&) = delete;

  // methods[method] on one case.
  IsolatedRun run(std::size_t method, const Region& subject, const Region& clip, Op op);

 private:
  static constexpr int kCasesPerWorker = 2000;
  void start();
  void stop(bool kill);
  [[noreturn]] void serve(int in, int out);

  std::vector<Method> methods_;
  IsolationLimits limits_;
  pid_t pid_ = -1;
  int toWorker_ = -1, fromWorker_ = -1;
  int served_ = 0;
};

}  // namespace gh::experiments
