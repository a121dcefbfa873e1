// libFuzzer target: small fuzzed inputs, the exact variant judged by the exact CGAL oracle.
// Any answer beyond the rounding tolerance traps.
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
    const auto v = gh::oracle::exactCheck(p.subject, p.clip, op, r, {false, false, false});
    if (!v.pass) {
      gh::fuzz::trap("exact oracle: error area " + std::to_string(v.errorArea) + " > tolerance " +
                         std::to_string(v.tolerance),
                     p.subject, p.clip, op);
    }
  }
  return 0;
}
