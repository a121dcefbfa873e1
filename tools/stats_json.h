// Statistics of a clip as JSON (the --stats output of the tools).
#pragma once

#include <nlohmann/json.hpp>

#include "ghclip/stats.h"

namespace gh::tools {

inline nlohmann::json statsJson(const Stats& s) {
  return {{"subject_vertices", s.subjectVertices},
          {"clip_vertices", s.clipVertices},
          {"candidate_pairs", s.candidatePairs},
          {"intersections", s.intersections},
          {"perturbations", s.perturbations},
          {"perturbation_rounds", s.perturbationRounds},
          {"filter_failures", s.filterFailures},
          {"expansion_decisions", s.expansionDecisions},
          {"exact_constructions", s.exactConstructions},
          {"output_rings", s.outputRings},
          {"output_vertices", s.outputVertices},
          {"phase1_seconds", s.phase1Seconds},
          {"phase2_seconds", s.phase2Seconds},
          {"phase3_seconds", s.phase3Seconds}};
}

}  // namespace gh::tools
