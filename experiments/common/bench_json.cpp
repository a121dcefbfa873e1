#include "bench_json.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "tool_main.h"

namespace gh::experiments {

namespace {

double toMs(double t, const std::string& unit) {
  if (unit == "ns") return t / 1e6;
  if (unit == "us") return t / 1e3;
  if (unit == "s") return t * 1e3;
  return t;
}

BenchFile readBenchJsonOrThrow(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw tools::BadInput(path + ": cannot open");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // Google Benchmark writes bare NaN / inf for undefined statistics (e.g. the coefficient of
  // variation of a constant counter); JSON has no such literals, so they become null.
  for (const std::string bad : {"-nan", "-NaN", "NaN", "nan", "-inf", "inf"}) {
    for (std::size_t pos = 0; (pos = text.find(": " + bad, pos)) != std::string::npos;) {
      text.replace(pos + 2, bad.size(), "null");
    }
  }
  const nlohmann::json doc = nlohmann::json::parse(text);
  BenchFile out;
  for (const auto& [k, v] : doc.at("context").items()) {
    if (v.is_string()) out.context[k] = v.get<std::string>();
    if (v.is_number()) out.context[k] = v.dump();
  }
  std::map<std::string, std::map<long, std::vector<double>>> times;
  for (const auto& b : doc.at("benchmarks")) {
    const std::string name = b.at("name").get<std::string>();
    // "<workload>/<method>/<n>/min_time:..." or "<workload>/<method>/min_time:..._BigO"
    const auto first = name.find('/'), second = name.find('/', first + 1);
    if (first == std::string::npos || second == std::string::npos) continue;
    const std::string family = name.substr(0, second);
    if (name.find("_BigO") != std::string::npos) {
      out.fits[family].bigO = b.value("big_o", "");
      out.fits[family].coefficient = b.value("real_coefficient", b.value("real_time", 0.0));
      continue;
    }
    if (name.find("_RMS") != std::string::npos) {
      out.fits[family].rms = b.value("rms", b.value("real_time", 0.0));
      continue;
    }
    if (b.value("run_type", "iteration") == "aggregate") continue;  // we compute our own
    if (b.contains("error_occurred") && b["error_occurred"].is_boolean() && b["error_occurred"].get<bool>()) continue;
    const long n = std::stol(name.substr(second + 1));
    const double ms = toMs(b.at("real_time").get<double>(), b.value("time_unit", "ns"));
    times[family][n].push_back(ms);
    BenchRow& row = out.rows[family][n];
    row.family = family;
    row.n = n;
    row.iterations += b.value("iterations", 0L);
    for (const auto& [k, v] : b.items()) {
      static const char* known[] = {"name", "run_name", "run_type", "repetitions", "repetition_index", "threads",
                                    "iterations", "real_time", "cpu_time", "time_unit", "family_index",
                                    "per_family_instance_index", "aggregate_name", "aggregate_unit", "complexity_n"};
      if (std::find(std::begin(known), std::end(known), k) != std::end(known) || !v.is_number()) continue;
      row.counters[k] = std::max(row.counters[k], v.get<double>());  // "wrong" is 1 if any run was wrong
    }
  }
  for (auto& [family, byN] : times) {
    for (auto& [n, ts] : byN) {
      std::sort(ts.begin(), ts.end());
      BenchRow& row = out.rows[family][n];
      row.repetitions = static_cast<int>(ts.size());
      row.minMs = ts.front(), row.maxMs = ts.back();
      row.medianMs = ts.size() % 2 ? ts[ts.size() / 2] : (ts[ts.size() / 2 - 1] + ts[ts.size() / 2]) / 2;
    }
  }
  if (out.rows.empty() && out.fits.empty()) throw tools::BadInput(path + ": holds no benchmark results");
  return out;
}

}  // namespace

BenchFile readBenchJson(const std::string& path) {
  try {
    return readBenchJsonOrThrow(path);
  } catch (const tools::BadInput&) {
    throw;
  } catch (const std::exception& e) {  // nlohmann's parse and type errors, a name without "/<n>"
    throw tools::BadInput(path + ": not Google Benchmark JSON: " + e.what());
  }
}

const BenchRow* findRow(const BenchFile& f, const std::string& family, long n) {
  const auto it = f.rows.find(family);
  if (it == f.rows.end()) return nullptr;
  const auto jt = it->second.find(n);
  return jt == it->second.end() ? nullptr : &jt->second;
}

double counterOf(const BenchRow* r, const std::string& name) {
  return r && r->counters.count(name) ? r->counters.at(name) : 0;
}

std::string reportNumber(double v) {
  std::ostringstream s;
  s.precision(v < 1 ? 3 : 4);
  s << v;
  return s.str();
}

std::string timeRange(const BenchRow& r, double scale) {
  std::string s = reportNumber(r.medianMs * scale);
  if (r.repetitions > 1) s += " [" + reportNumber(r.minMs * scale) + "–" + reportNumber(r.maxMs * scale) + "]";
  return s;
}

}  // namespace gh::experiments
