#include "pipeline/plots.h"

#include <algorithm>
#include <cstdlib>
#include <sstream>

#include "capture/colmap_runner.h"
#include "core/error.h"
#include "core/files.h"

namespace voltree {
namespace fs = std::filesystem;

namespace {

// gnuplot single-quoted string: no escapes are interpreted, '' stands for one quote.
std::string Quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) {
    if (c == '\'')
      out += "''";
    else if (c != '\n')
      out += c;
  }
  return out + "'";
}

}  // namespace

bool PlotSpec::HasPoints() const {
  for (const PlotSeries& s : series)
    if (!s.points.empty()) return true;
  return false;
}

std::optional<Gnuplot> FindGnuplot(const fs::path& log, std::string* why_not) {
  const char* path = std::getenv("PATH");
  Gnuplot gnuplot;
  try {
    gnuplot.program = FindExecutable("gnuplot", path ? path : "", "apt-get install gnuplot-nox");
  } catch (const Error& error) {
    if (why_not) *why_not = error.what();
    return std::nullopt;
  }
  for (const char* terminal : {"pngcairo", "png"}) {
    if (RunChild(gnuplot.program, {"-e", Str("set terminal ", terminal)}, log).ok()) {
      gnuplot.terminal = terminal;
      return gnuplot;
    }
  }
  if (why_not) *why_not = Str(gnuplot.program.string(), " has neither the pngcairo nor the png terminal");
  return std::nullopt;
}

std::string GnuplotScript(const PlotSpec& spec, const std::string& terminal, const fs::path& output) {
  std::ostringstream gp;
  gp << "set terminal " << terminal << " size " << spec.width << "," << spec.height
     << (terminal == "pngcairo" ? " font 'sans,10'" : "") << "\n";
  gp << "set output " << Quote(output.string()) << "\n";
  gp << "set title " << Quote(spec.title) << "\n";
  gp << "set xlabel " << Quote(spec.x_label) << "\nset ylabel " << Quote(spec.y_label) << "\n";
  gp << "set grid\nset key bottom right\n";
  if (spec.integer_x) gp << "set xtics 1\n";
  if (spec.log_x) gp << "set logscale x 2\n";
  if (spec.y_range) gp << "set yrange [" << spec.y_range->first << ":" << spec.y_range->second << "]\n";
  std::vector<const PlotSeries*> drawn;
  for (const PlotSeries& s : spec.series)
    if (!s.points.empty()) drawn.push_back(&s);
  if (drawn.size() == 1) gp << "set key off\n";  // the title says what the one series is
  if (spec.style == PlotStyle::kBars && !drawn.empty()) {
    // Bars half a unit either side of the outermost x; gnuplot's autoscale pads to round tics.
    double lo = drawn.front()->points.front().first, hi = lo;
    for (const PlotSeries* s : drawn)
      for (const auto& point : s->points) lo = std::min(lo, point.first), hi = std::max(hi, point.first);
    gp << "set style fill solid 0.6 border -1\nset boxwidth 0.6\nset xrange [" << lo - 0.5 << ":" << hi + 0.5 << "]\n";
    if (!spec.y_range) gp << "set yrange [0:*]\n";
  }
  gp << "plot ";
  for (size_t i = 0; i < drawn.size(); ++i) {
    gp << (i ? ", " : "") << "'-' using 1:2 with "
       << (spec.style == PlotStyle::kBars ? "boxes" : "linespoints pointtype 7") << " title " << Quote(drawn[i]->title);
  }
  gp << "\n";
  gp.precision(10);
  for (const PlotSeries* s : drawn) {
    for (const auto& [x, y] : s->points) gp << x << " " << y << "\n";
    gp << "e\n";
  }
  return gp.str();
}

void DrawPlot(const Gnuplot& gnuplot, const PlotSpec& spec, const fs::path& folder) {
  if (!spec.HasPoints()) Fail("plot ", spec.file, ": no data points");
  const fs::path output = folder / spec.file;
  const fs::path script = fs::path(output).replace_extension(".gp");
  const fs::path log = fs::path(output).replace_extension(".log");
  // The script names the PNG by its file name and gnuplot runs in the folder, so the kept
  // script redraws the plot wherever the report is moved.
  WriteFileAtomic(script, GnuplotScript(spec, gnuplot.terminal, spec.file));
  const ChildResult result = RunChild(
      gnuplot.program, {"-e", Str("cd ", Quote(fs::absolute(folder).string())), fs::absolute(script).string()}, log);
  if (!result.ok() || !fs::exists(output))
    Fail("gnuplot failed drawing ", output.string(), " (log ", log.string(), "):\n", LogTail(log, 8));
  std::error_code ignored;
  fs::remove(log, ignored);  // empty or warnings only: the plot is there
}

}  // namespace voltree
