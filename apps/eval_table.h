// The short table that `voltree eval`, `voltree run` and `voltree demo` print at the end.
#pragma once

#include <string>

#include "pipeline/evaluate.h"
#include "pipeline/evaluation_levels.h"

namespace voltree::app {

// Held-out and input rows (auto LOD, means over the views): RGB PSNR, SSIM, alpha PSNR, P, R, RMS.
std::string EvaluationTable(const LevelMetricsTable& table);

// The table, eval's notes and the path of the report page, on stdout.
void PrintEvaluation(const EvaluateResult& result);

}  // namespace voltree::app
