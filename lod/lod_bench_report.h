// What `voltree lod-bench` writes: table.md (the measured table and Neubert's scale search),
// lod_bench.json (the same numbers) and gnuplot plots (quality against triangles and against
// fragments, the PR diagram of Neubert et al. 2011 fig. 2, multi-scale RMS against screen size).
#pragma once

#include <filesystem>
#include <string>

#include "core/progress.h"
#include "lod/lod_bench.h"

namespace voltree {

std::string LodBenchTable(const LodBenchResult& result);
std::string LodBenchJson(const LodBenchResult& result);

// Writes the files into `folder` (which exists); plots only when gnuplot is installed, else a
// progress line says why not.
void WriteLodBench(const LodBenchResult& result, const std::filesystem::path& folder, Progress& progress);

}  // namespace voltree
