// Peak memory of one clip per crossing, on the paper's random workload (Table 1's pools, the first
// pair of each), every variant on one thread: each case in a child process, which resets the
// kernel's resident high-water mark after generating its input (/proc/self/clear_refs, 5) and
// reads it after the clip (VmHWM). The bytes the clip added at its peak, over its crossings,
// include everything it touched: phase 1's buffers, the graph, the traced rings and the answer.
//   clip_memory OUT.md
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "common/bench_json.h"
#include "common/provenance.h"
#include "ghclip/clip.h"
#include "ghio/formats.h"
#include "ghwork/generators.h"
#include "tool_main.h"

namespace {

long statusKb(const char* key) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind(key, 0) == 0) return std::atol(line.c_str() + std::string(key).size());
  }
  return -1;
}

// "<crossings> <bytes>" from a child that clips pair 0 of the pool of (random, n).
std::pair<double, double> measure(const std::string& variant, std::size_t n) {
  int pipeFds[2];
  if (pipe(pipeFds) != 0) throw std::runtime_error("pipe failed");
  const pid_t child = fork();
  if (child < 0) throw std::runtime_error("fork failed");
  if (child == 0) {
    close(pipeFds[0]);
    const gh::work::Workload w = gh::work::generate("random", n, 1000);
    { std::ofstream("/proc/self/clear_refs") << "5"; }
    const long before = statusKb("VmRSS:");
    gh::Stats stats;
    const gh::Region r = gh::clip(w.subject, w.clip, gh::Op::Intersection, *gh::parseOptions(variant), &stats);
    const long peak = statusKb("VmHWM:");
    const std::string out = std::to_string(stats.intersections) + " " + std::to_string((peak - before) * 1024L) + "\n";
    if (write(pipeFds[1], out.data(), out.size()) < 0) _exit(1);
    _exit(r.empty() ? 1 : 0);
  }
  close(pipeFds[1]);
  char buffer[128] = {};
  const ssize_t got = read(pipeFds[0], buffer, sizeof buffer - 1);
  close(pipeFds[0]);
  int status = 0;
  waitpid(child, &status, 0);
  double crossings = 0, bytes = 0;
  if (got <= 0 || std::sscanf(buffer, "%lf %lf", &crossings, &bytes) != 2) throw std::runtime_error("a measurement failed");
  return {crossings, bytes};
}

}  // namespace

int run(int argc, char** argv) {
  if (argc != 2) return gh::tools::usageError("clip_memory", "usage: clip_memory OUT.md");
  std::ostringstream md;
  md << "# Peak memory of a clip, per crossing\n\n" << gh::experiments::markdown(gh::experiments::provenance(argc, argv))
     << "\nThe paper's workload (the first pair of Table 1's pool at each n), intersection, one thread. Each case "
        "runs in a child process that resets the kernel's resident high-water mark after generating its input and "
        "reads it after the clip: the bytes the clip added at its peak (phase 1's buffers, the vertex graph, the "
        "traced rings and the answer), over its crossings.\n\n"
     << "| n | crossings | naive: peak MB | naive: bytes per crossing | exact: peak MB | exact: bytes per crossing |\n"
     << "|---|---|---|---|---|---|\n";
  for (std::size_t n : {100, 200, 500, 1000, 2000}) {
    const auto [kn, bn] = measure("naive", n);
    const auto [ke, be] = measure("exact", n);
    md << "| " << n << " | " << gh::experiments::reportNumber(kn) << " | " << gh::experiments::reportNumber(bn / 1048576)
       << " | " << gh::experiments::reportNumber(bn / kn) << " | " << gh::experiments::reportNumber(be / 1048576) << " | "
       << gh::experiments::reportNumber(be / ke) << " |\n";
  }
  gh::io::writeText(argv[1], md.str());
  std::cout << "wrote " << argv[1] << "\n";
  return 0;
}

int main(int argc, char** argv) { return gh::tools::guardedMain("clip_memory", argc, argv, run); }
