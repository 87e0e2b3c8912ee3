// Line and bar charts of measured data, drawn by gnuplot (Debian: gnuplot-nox) as a child
// process writing PNG. Nothing here invents data: a plot gets only the points it is given, and a
// plot without points is not drawn.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace voltree {

struct PlotSeries {
  std::string title;
  std::vector<std::pair<double, double>> points;  // (x, y), drawn in this order
};

enum class PlotStyle { kLines, kBars };

struct PlotSpec {
  std::string file;  // PNG file name inside the plot folder, e.g. "psnr_per_level.png"
  std::string title, x_label, y_label;
  std::vector<PlotSeries> series;
  PlotStyle style = PlotStyle::kLines;
  bool integer_x = false;  // one tic per integer (octree levels)
  bool log_x = false;      // base-2 logarithmic x (codebook sizes)
  std::optional<std::pair<double, double>> y_range;
  int width = 640, height = 400;
  bool HasPoints() const;
};

struct Gnuplot {
  std::filesystem::path program;
  std::string terminal;  // "pngcairo", or "png" (libgd) when cairo is not built in
};

// gnuplot on PATH with a PNG terminal, or nothing with `why_not` saying what is missing. `log` is
// where the probe's output goes.
std::optional<Gnuplot> FindGnuplot(const std::filesystem::path& log, std::string* why_not);

// The whole gnuplot script of a plot, data inline ('-' blocks). Strings are quoted for gnuplot.
std::string GnuplotScript(const PlotSpec& spec, const std::string& terminal, const std::filesystem::path& output);

// Writes FOLDER/spec.file through gnuplot; the script stays beside it (.gp) so the plot can be
// redrawn, gnuplot's log (.log) only when it failed. Throws Error with the log's tail then.
void DrawPlot(const Gnuplot& gnuplot, const PlotSpec& spec, const std::filesystem::path& folder);

}  // namespace voltree
