#include "judge.h"

#include "ghclip/errors.h"
#include "ghpeers/peer.h"

namespace gh::experiments {

Judged judge(const Method& m, const Region& subject, const Region& clip, Op op) {
  Judged j;
  try {
    j.result = m.clip(subject, clip, op);
  } catch (const peers::PeerRefusal& e) {
    j.outcome = Outcome::Refused;
    j.message = e.what();
    return j;
  } catch (const std::exception& e) {
    j.outcome = Outcome::Failed;
    j.message = e.what();
    return j;
  }
  try {
    j.outcome = judgeAnswer(subject, clip, op, j.result, j.relativeError);
  } catch (const oracle::CannotJudge& e) {
    j.outcome = Outcome::CannotJudge;
    j.message = e.what();
  }
  return j;
}

Outcome judgeAnswer(const Region& subject, const Region& clip, Op op, const Region& result, double& relativeError) {
  return outcomeOf(oracle::exactCheck(subject, clip, op, result, {false, false, true}), relativeError);
}

Outcome outcomeOf(const oracle::ExactVerdict& v, double& relativeError) {
  relativeError = v.relativeError();
  if (v.errorAreaExact == "0") return Outcome::Exact;
  if (v.pass) return Outcome::Rounding;
  return relativeError > 1e-6 ? Outcome::Gross : Outcome::BeyondRounding;
}

}  // namespace gh::experiments
