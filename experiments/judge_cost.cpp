// Where a clip fuzz target's execution goes: the clip (the five operations) against its judges
// (the invariants, the sampling oracle, the boundary certificate, and the three as
// fuzz/clip_target.h runs them), timed side by side
// in one run on the fuzz inputs pinned by tests/golden/judge_verdicts.golden (seeds, regressions
// and grown corpora of the clip targets), in a release build without sanitizers. Each timed
// iteration runs one stage over every input that is not refused; repetitions interleaved in
// random order; medians. The fuzz targets' exec/s (./harness fuzz) also pays ASan and UBSan on
// the clip, libFuzzer and fork mode: this says how the work itself divides, which a faster judge
// must change (issue 19 asks the clip targets for 1,000 executions a second).
//   judge_cost OUT.md [google benchmark flags]
#include <benchmark/benchmark.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "clip_target.h"
#include "judge_pins.h"
#include "common/bench_json.h"
#include "common/bench_run.h"
#include "common/provenance.h"
#include "ghio/formats.h"
#include "tool_main.h"

using namespace gh;
using namespace gh::experiments;

namespace {

constexpr int kRepetitions = 9;

struct Variant_ {
  const char* name;
  Variant variant;
};
const Variant_ kVariants[] = {{"naive", Variant::Naive}, {"exact", Variant::Exact}};

// A pinned input with its answers (computed once, for the judges' stages), and for the exact
// variant its answers as written (the OGC layout), which the target judges too.
struct Execution {
  fuzz::Pair pair;
  std::vector<std::pair<Op, Region>> answers, written;
};

// The pinned inputs a variant does not refuse, with its five answers (those it gives).
std::vector<Execution> executions(Variant variant) {
  const std::vector<fuzz::JudgePin> pins = fuzz::readJudgePins(GHCLIP_JUDGE_VERDICTS_FILE);
  if (pins.empty()) throw tools::BadInput(std::string("no pinned inputs in ") + GHCLIP_JUDGE_VERDICTS_FILE);
  std::vector<Execution> out;
  for (const fuzz::JudgePin& pin : pins) {
    const auto bytes = fuzz::bytesOfHex(pin.hex);
    Execution e{fuzz::clipPair(bytes.data(), bytes.size()), {}, {}};
    fuzz::ClipOutcome outcome;
    e.answers = fuzz::clipFive(e.pair, variant, outcome, variant == Variant::Exact ? &e.written : nullptr);
    if (outcome.refused) continue;
    out.push_back(std::move(e));
  }
  return out;
}

const std::vector<Execution>& executionsOf(Variant variant) {
  static std::optional<std::vector<Execution>> cached[3];
  auto& slot = cached[static_cast<int>(variant)];
  if (!slot) slot = executions(variant);
  return *slot;
}

void clipStage(benchmark::State& s, Variant variant) {
  const auto& all = executionsOf(variant);
  for (auto _ : s) {
    for (const Execution& e : all) {
      fuzz::ClipOutcome outcome;
      std::vector<std::pair<Op, Region>> written;
      benchmark::DoNotOptimize(fuzz::clipFive(e.pair, variant, outcome, variant == Variant::Exact ? &written : nullptr));
    }
  }
  s.counters["executions"] = static_cast<double>(all.size());
}

void invariantsStage(benchmark::State& s, Variant variant) {
  const auto& all = executionsOf(variant);
  for (auto _ : s) {
    for (const Execution& e : all) {
      if (e.answers.empty()) continue;
      const oracle::InvariantJudge invariants(e.pair.subject, e.pair.clip);
      for (const auto& [op, r] : e.answers) benchmark::DoNotOptimize(invariants.violations(op, r));
    }
  }
  s.counters["executions"] = static_cast<double>(all.size());
}

void samplingStage(benchmark::State& s, Variant variant) {
  const auto& all = executionsOf(variant);
  double points = 0, failed = 0;
  for (auto _ : s) {
    points = failed = 0;
    for (const Execution& e : all) {
      if (e.answers.empty()) continue;
      std::vector<std::pair<Op, const Region*>> judged;
      for (const auto& [op, r] : e.answers) judged.emplace_back(op, &r);
      for (const oracle::SampleVerdict& v : oracle::SamplingJudge(e.pair.subject, e.pair.clip, fuzz::clipTargetSampling()).check(judged)) {
        points += static_cast<double>(v.checked + v.skipped);
        failed += !v.pass();
      }
    }
  }
  s.counters["executions"] = static_cast<double>(all.size());
  s.counters["points_per_answer"] = points / (5.0 * static_cast<double>(all.size()));
  s.counters["answers_failed"] = failed;
}

void certificateStage(benchmark::State& s, Variant variant) {
  const auto& all = executionsOf(variant);
  double proved = 0;
  for (auto _ : s) {
    proved = 0;
    for (const Execution& e : all) {
      if (e.answers.empty()) continue;
      std::vector<std::pair<Op, const Region*>> judged;
      for (const auto& [op, r] : e.answers) judged.emplace_back(op, &r);
      const std::vector<bool> c = oracle::certifiedAnswers(e.pair.subject, e.pair.clip, judged);
      proved += std::all_of(c.begin(), c.end(), [](bool b) { return b; });
    }
  }
  s.counters["executions"] = static_cast<double>(all.size());
  s.counters["proved"] = proved;
}

// The judges as the target runs them (fuzz::judgeFive): the invariants, then the certificate for
// the exact variant and the sampling oracle where it does not prove all five; for the exact
// variant on its answers as written too.
void targetJudgesStage(benchmark::State& s, Variant variant) {
  const auto& all = executionsOf(variant);
  for (auto _ : s) {
    for (const Execution& e : all) {
      if (e.answers.empty()) continue;
      fuzz::ClipOutcome outcome;
      fuzz::judgeFive(e.pair, variant, e.answers, outcome);
      if (!e.written.empty()) fuzz::judgeFive(e.pair, variant, e.written, outcome, "written answer: ");
      benchmark::DoNotOptimize(outcome);
    }
  }
  s.counters["executions"] = static_cast<double>(all.size());
}

}  // namespace

int run(int argc, char** argv) {
  if (argc < 2 || std::string(argv[1]).rfind("--", 0) == 0) {
    return tools::usageError("judge_cost", "usage: judge_cost OUT.md [google benchmark flags]");
  }
  const std::string out = argv[1];
  const std::string json = std::filesystem::path(out).replace_extension(".json").string();
  const struct {
    const char* name;
    void (*stage)(benchmark::State&, Variant);
  } stages[] = {{"clip", clipStage},
                {"invariants", invariantsStage},
                {"sampling", samplingStage},
                {"certificate", certificateStage},
                {"target-judges", targetJudgesStage}};
  for (const Variant_& v : kVariants) {
    for (const auto& st : stages) {
      benchmark::RegisterBenchmark((std::string(v.name) + "/" + st.name).c_str(),
                                   [v, st](benchmark::State& s) { st.stage(s, v.variant); })
          ->Arg(1)->Iterations(1)->Repetitions(kRepetitions)->Unit(benchmark::kMillisecond);
    }
  }
  const std::optional<BenchFile> ran = runInterleaved(argc, argv, 2, json);
  if (!ran) return 0;  // listed only
  const BenchFile& f = *ran;

  std::ostringstream md;
  md << "# Where a clip fuzz target's execution goes: the clip against its judges\n\n"
     << markdown(provenance(argc, argv)) << "\n"
     << "The fuzz inputs pinned by `tests/golden/judge_verdicts.golden` (the clip targets' seeds, "
        "regressions and grown corpora), those the variant does not refuse; per execution, the five "
        "operations clipped (`Clipping`, as the targets do; for the exact variant each laid out as written "
        "too, the OGC layout checked valid), the invariants on the five answers, and "
        "the sampling oracle on the five at once with the targets' options (200 uniform points, "
        "stop when every answer has failed: `fuzz/clip_target.h`). Release build, no sanitizers; "
        "each timed iteration runs one stage over every input; "
     << kRepetitions
     << " repetitions, interleaved in random order; medians [min-max] in µs per execution. The boundary "
        "certificate (`ghoracle/boundary_certificate.h`) on the five answers at once, and the "
        "executions whose five it proves; the target's judges: the invariants, then for the exact "
        "variant the certificate, and the sampling oracle where it does not prove all five "
        "(`fuzz::judgeFive`), for the exact variant on its answers as written too. A fuzz target's executions also pay ASan and UBSan on the clip, "
        "libFuzzer and fork mode (`./harness fuzz` reports what they reach).\n\n"
     << "| variant | executions | clip µs | invariants µs | sampling oracle µs | certificate µs | proved "
        "| the target's judges µs | its judges / clip | points per answer | answers failed |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Variant_& v : kVariants) {
    const BenchRow* clip = findRow(f, std::string(v.name) + "/clip", 1);
    const BenchRow* inv = findRow(f, std::string(v.name) + "/invariants", 1);
    const BenchRow* smp = findRow(f, std::string(v.name) + "/sampling", 1);
    const BenchRow* cert = findRow(f, std::string(v.name) + "/certificate", 1);
    const BenchRow* judges = findRow(f, std::string(v.name) + "/target-judges", 1);
    const double executions = counterOf(clip, "executions");
    const double perExecution = executions > 0 ? 1000 / executions : 0;  // ms per iteration -> µs per execution
    auto cell = [&](const BenchRow* r) { return r && executions > 0 ? timeRange(*r, perExecution) : std::string("–"); };
    md << "| " << v.name << " | " << reportNumber(executions) << " | " << cell(clip) << " | " << cell(inv) << " | "
       << cell(smp) << " | " << cell(cert) << " | " << (cert ? reportNumber(counterOf(cert, "proved")) : "–") << " | "
       << cell(judges) << " | " << (clip && judges ? reportNumber(judges->medianMs / clip->medianMs) : "–") << " | "
       << (smp ? reportNumber(counterOf(smp, "points_per_answer")) : "–") << " | "
       << (smp ? reportNumber(counterOf(smp, "answers_failed")) : "–") << " |\n";
  }
  io::writeText(out, md.str());
  std::cout << "wrote " << out << "\n";
  return 0;
}

int main(int argc, char** argv) { return tools::guardedMain("judge_cost", argc, argv, run); }
