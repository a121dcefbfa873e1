#include "judge.h"

#include "ghclip/errors.h"
#include "ghoracle/peer.h"

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
  const auto v = oracle::exactCheck(subject, clip, op, j.result, {false, false, true});
  j.relativeError = v.relativeError();
  if (v.errorAreaExact == "0") {
    j.outcome = Outcome::Exact;
  } else if (v.pass) {
    j.outcome = Outcome::Rounding;
  } else {
    j.outcome = j.relativeError > 1e-6 ? Outcome::Gross : Outcome::BeyondRounding;
  }
  return j;
}

}  // namespace gh::experiments
