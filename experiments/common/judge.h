// Run a method on one case and judge the answer with the exact oracle.
#pragma once

#include <string>

#include "ghoracle/exact_oracle.h"
#include "methods.h"

namespace gh::experiments {

struct Judged {
  Outcome outcome = Outcome::Failed;
  double relativeError = 0;
  std::string message;  // refusal or failure reason
  Region result;
};

Judged judge(const Method& m, const Region& subject, const Region& clip, Op op);

// The outcome of an answer R to op(S, C) by the exact oracle (Exact, Rounding, BeyondRounding or
// Gross), and its relative error area. Throws what exactCheck throws (unreadable answers,
// oracle::CannotJudge).
Outcome judgeAnswer(const Region& subject, const Region& clip, Op op, const Region& result, double& relativeError);

// The outcome of one verdict (with its exact error area).
Outcome outcomeOf(const oracle::ExactVerdict& v, double& relativeError);

}  // namespace gh::experiments
