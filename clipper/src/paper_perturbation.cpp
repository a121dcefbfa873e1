#include "paper_perturbation.h"

#include <algorithm>
#include <cmath>

namespace gh::detail {

std::size_t perturb(Operand& subject, Operand& clip, const Degeneracies& degeneracies, int round) {
  double scale = 0;
  for (const Operand* op : {&subject, &clip}) {
    for (const Point& p : op->vertices) scale = std::max({scale, std::abs(p.x), std::abs(p.y)});
  }
  constexpr double kGoldenAngle = 2.399963229728653;
  const double angle = 0.5 + kGoldenAngle * round;
  const double length = kPerturbationScale * scale;
  const Point move{length * std::cos(angle), length * std::sin(angle)};
  const bool moveClip = !degeneracies.clip.empty();
  Operand& target = moveClip ? clip : subject;
  const std::vector<std::uint32_t>& vs = moveClip ? degeneracies.clip : degeneracies.subject;
  for (std::uint32_t v : vs) {
    target.vertices[v].x += move.x;
    target.vertices[v].y += move.y;
  }
  return vs.size();
}

}  // namespace gh::detail
