#include "layout/traced_lines.h"

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
  // The operand edges used, numbered as lines in order of first use.
  const std::uint32_t subjectEdges = static_cast<std::uint32_t>(subject.size());
  std::vector<std::uint32_t> lineOfEdge(subject.size() + clip.size(), 0xffffffffu);
  for (std::size_t k = 0; k < lines.size(); ++k) {
    const std::uint32_t edge = lines[k] & ~kTracedCrossing;
    if (lineOfEdge[edge] == 0xffffffffu) {
      lineOfEdge[edge] = static_cast<std::uint32_t>(out.lines.size());
      const Operand& op = edge < subjectEdges ? subject : clip;
      const std::uint32_t e = edge < subjectEdges ? edge : edge - subjectEdges;
      out.lines.push_back({op.from(e), op.to(e)});
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
