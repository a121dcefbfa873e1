#include "layout/traced_lines.h"

#include <algorithm>

#include "phase3_tracing.h"
#include "predicates/orientation.h"

namespace gh::detail {

LinedRings tracedLines(const FlatRings& traced, const std::vector<std::uint32_t>& lines, const Operand& subject,
                       const Operand& clip, ExactCounters& counters) {
  LinedRings out;
  out.points = traced.points;
  out.ringStart = traced.start;
  out.line.resize(lines.size());
  out.exact.resize(lines.size());
  // The operand edges used, numbered as lines in order of first use; edges with the same two ends
  // (either way round: a ring of S repeated in C) are one line, so that their crossings are one
  // point by definition (exact_noding.h need not compare them).
  const std::uint32_t subjectEdges = static_cast<std::uint32_t>(subject.size());
  std::vector<std::uint32_t> lineOfEdge(subject.size() + clip.size(), 0xffffffffu);
  auto lexLess = [](Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); };
  // The edges in order of first use, then sorted by their ends (a sort, not a hash map of
  // vectors: a million edges' worth of small allocations was a fifth of the layout's time).
  struct Use {
    Point lo, hi;
    std::uint32_t edge, order;
  };
  std::vector<Use> uses;
  for (std::size_t k = 0; k < lines.size(); ++k) {
    const std::uint32_t edge = lines[k] & ~kTracedCrossing;
    if (lineOfEdge[edge] != 0xffffffffu) continue;
    lineOfEdge[edge] = 0;  // seen
    const Operand& op = edge < subjectEdges ? subject : clip;
    const std::uint32_t e = edge < subjectEdges ? edge : edge - subjectEdges;
    const Point a = op.from(e), b = op.to(e);
    uses.push_back({lexLess(a, b) ? a : b, lexLess(a, b) ? b : a, edge, static_cast<std::uint32_t>(uses.size())});
  }
  std::vector<Use> byEnds = uses;
  std::stable_sort(byEnds.begin(), byEnds.end(), [&](const Use& u, const Use& v) {
    if (lexLess(u.lo, v.lo) || lexLess(v.lo, u.lo)) return lexLess(u.lo, v.lo);
    if (lexLess(u.hi, v.hi) || lexLess(v.hi, u.hi)) return lexLess(u.hi, v.hi);
    return u.order < v.order;
  });
  std::vector<std::uint32_t> firstOfSame(uses.size());  // by order: the first use with the same ends
  for (std::size_t i = 0; i < byEnds.size(); ++i) {
    const bool same = i > 0 && byEnds[i].lo == byEnds[i - 1].lo && byEnds[i].hi == byEnds[i - 1].hi;
    firstOfSame[byEnds[i].order] = same ? firstOfSame[byEnds[i - 1].order] : byEnds[i].order;
  }
  for (const Use& u : uses) {
    if (firstOfSame[u.order] == u.order) {
      lineOfEdge[u.edge] = static_cast<std::uint32_t>(out.lines.size());
      const Operand& op = u.edge < subjectEdges ? subject : clip;
      const std::uint32_t e = u.edge < subjectEdges ? u.edge : u.edge - subjectEdges;
      out.lines.push_back({op.from(e), op.to(e)});
    } else {
      lineOfEdge[u.edge] = lineOfEdge[uses[firstOfSame[u.order]].edge];
    }
  }
  for (std::size_t k = 0; k < lines.size(); ++k) out.line[k] = lineOfEdge[lines[k] & ~kTracedCrossing];
  for (std::size_t r = 0; r + 1 < out.ringStart.size(); ++r) {
    const std::uint32_t first = out.ringStart[r], end = out.ringStart[r + 1];
    for (std::uint32_t k = first; k < end; ++k) {
      if (!(lines[k] & kTracedCrossing)) {
        out.exact[k] = 1;
        continue;
      }
      // The crossing of the edge it arrives along and the edge it leaves along: exactly an input
      // vertex when it is an end of one that lies on the other.
      const LinedRings::Line &a = out.lines[out.line[k > first ? k - 1 : end - 1]], &b = out.lines[out.line[k]];
      const Point p = out.points[k];
      auto isEndOn = [&](const LinedRings::Line& m, const LinedRings::Line& n) {
        return (p == m.from || p == m.to) && orientation(n.from, n.to, p, counters) == Sign::Zero;
      };
      out.exact[k] = isEndOn(a, b) || isEndOn(b, a);
    }
  }
  return out;
}

}  // namespace gh::detail
