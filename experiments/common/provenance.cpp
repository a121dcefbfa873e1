#include "provenance.h"

#include <sys/utsname.h>
#include <unistd.h>

#include <cstdlib>
#include <ctime>
#include <fstream>
#include <sstream>

#include "build_info.h"

namespace gh::experiments {
namespace {

std::string cpuModel() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) return line.substr(colon + 2);
    }
  }
  return "unknown CPU";
}

}  // namespace

Provenance provenance(int argc, char** argv) {
  Provenance p;
  for (int i = 0; i < argc; ++i) p.command += (i ? " " : "") + std::string(argv[i]);
  const char* commit = std::getenv("GHCLIP_COMMIT");
  p.commit = commit && *commit ? commit : "unknown";
  p.compiler = kCompiler;
  p.flags = kFlags;
  utsname u{};
  uname(&u);
  const long cores = sysconf(_SC_NPROCESSORS_ONLN);
  const double gib = static_cast<double>(sysconf(_SC_PHYS_PAGES)) *
                     static_cast<double>(sysconf(_SC_PAGE_SIZE)) / (1024.0 * 1024 * 1024);
  std::ostringstream m;
  m.precision(3);
  m << cpuModel() << ", " << cores << " cores, " << gib << " GiB, " << u.sysname << ' '
    << u.release << ' ' << u.machine;
  p.machine = m.str();
  char buf[64];
  const std::time_t now = std::time(nullptr);
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  p.date = buf;
  return p;
}

std::string markdown(const Provenance& p) {
  std::ostringstream s;
  s << "| made by | `" << p.command << "` |\n|---|---|\n"
    << "| commit | " << p.commit << " |\n"
    << "| compiler | " << p.compiler << " |\n"
    << "| flags | `" << p.flags << "` |\n"
    << "| machine | " << p.machine << " |\n"
    << "| date | " << p.date << " |\n";
  return s.str();
}

}  // namespace gh::experiments
