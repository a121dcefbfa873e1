// Oracle verdicts as JSON and as one human-readable block (ghcheck, ghclip --check).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "ghoracle/exact_oracle.h"
#include "ghoracle/sampling_oracle.h"

namespace gh::tools {

nlohmann::json verdictJson(const oracle::ExactVerdict& v);
nlohmann::json verdictJson(const oracle::SampleVerdict& v);
std::string verdictText(const oracle::ExactVerdict& v);
std::string verdictText(const oracle::SampleVerdict& v);

}  // namespace gh::tools
