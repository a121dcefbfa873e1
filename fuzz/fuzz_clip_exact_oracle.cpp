// libFuzzer target: small fuzzed inputs, the exact variant judged by the exact CGAL oracle.
// Any answer with a wrong face beyond the rounding zones traps; a case the oracle cannot judge is
// recorded (counted apart), never a pass.
#include "findings.h"
#include "fuzz_input.h"
#include "ghclip/clip.h"
#include "ghclip/errors.h"
#include "ghoracle/exact_oracle.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const gh::fuzz::Pair p = gh::fuzz::pair(data, size, 2, 8);
  for (gh::Op op : gh::kAllOps) {
    gh::Options o = gh::optionsOf(gh::Variant::Exact);
    gh::Region r;
    try {
      r = gh::clip(p.subject, p.clip, op, o);
    } catch (const gh::InvalidInput&) {
      return 0;
    } catch (const gh::ClipFailure& e) {
      gh::fuzz::trap(std::string("ClipFailure: ") + e.what(), p.subject, p.clip, op);
    }
    gh::oracle::ExactVerdict v;
    try {
      v = gh::oracle::exactCheck(p.subject, p.clip, op, r, {false, false, false});
    } catch (const gh::oracle::CannotJudge& e) {
      gh::fuzz::record("fuzz_clip_exact_oracle", std::string("cannot judge: ") + e.what(), p.subject,
                       p.clip, op, data, size);
      continue;
    }
    if (!v.pass) {
      gh::fuzz::trap("exact oracle: wrong faces beyond rounding, area " + std::to_string(v.beyondRoundingArea) +
                         " (error area " + std::to_string(v.errorArea) + ")",
                     p.subject, p.clip, op);
    }
  }
  return 0;
}
