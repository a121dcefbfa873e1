#include "layout/traced_lines.h"

#include <unordered_map>

#include "phase3_tracing.h"
#include "point_hash.h"
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
  std::unordered_map<Point, std::vector<std::uint32_t>, PointHash> linesFrom;  // by the smaller end
  auto lexLess = [](Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); };
  for (std::size_t k = 0; k < lines.size(); ++k) {
    const std::uint32_t edge = lines[k] & ~kTracedCrossing;
    if (lineOfEdge[edge] == 0xffffffffu) {
      const Operand& op = edge < subjectEdges ? subject : clip;
      const std::uint32_t e = edge < subjectEdges ? edge : edge - subjectEdges;
      const Point a = op.from(e), b = op.to(e), lo = lexLess(a, b) ? a : b, hi = lexLess(a, b) ? b : a;
      std::vector<std::uint32_t>& same = linesFrom[lo];
      for (const std::uint32_t l : same) {
        const LinedRings::Line& m = out.lines[l];
        if ((m.from == lo && m.to == hi) || (m.from == hi && m.to == lo)) lineOfEdge[edge] = l;
      }
      if (lineOfEdge[edge] == 0xffffffffu) {
        lineOfEdge[edge] = static_cast<std::uint32_t>(out.lines.size());
        same.push_back(lineOfEdge[edge]);
        out.lines.push_back({a, b});
      }
    }
    out.line[k] = lineOfEdge[edge];
  }
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
