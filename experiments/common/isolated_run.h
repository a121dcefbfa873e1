// Runs one method on one case in a child process, so that a crash, a hang or a runaway allocation
// in a peer library ends that case only, never the experiment.
#pragma once

#include <string>

#include "methods.h"

namespace gh::experiments {

struct IsolatedRun {
  enum class Status { Answered, Refused, Threw, Crashed, TimedOut };
  Status status = Status::Threw;
  Region result;        // when Answered
  std::string message;  // refusal or exception text, or which signal ended the child
};

struct IsolationLimits {
  double seconds = 20;                            // wall time before the child is killed
  unsigned long long addressSpaceBytes = 8ull << 30;  // RLIMIT_AS of the child
};

IsolatedRun runIsolated(const Method& method, const Region& subject, const Region& clip, Op op,
                        const IsolationLimits& limits = {});

}  // namespace gh::experiments
