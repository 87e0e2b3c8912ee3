#include "view/viewer_script.h"

#include <sstream>

#include "core/error.h"
#include "core/files.h"

namespace voltree {

std::vector<ViewerEvent> ParseViewerScript(std::string_view text, const std::string& name) {
  std::vector<ViewerEvent> events;
  std::istringstream lines{std::string(text)};
  int number = 0;
  for (std::string line; std::getline(lines, line);) {
    ++number;
    if (const size_t hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    std::istringstream words(line);
    ViewerEvent event;
    if (!(words >> event.seconds)) {
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
      Fail(name, ":", number, ": expected SECONDS ACTION [ARGS], got '", line, "'");
    }
    const std::string where = Str(name, ":", number, ": ");
    if (!(event.seconds >= 0) || (!events.empty() && event.seconds < events.back().seconds))
      Fail(where, "times must be >= 0 and not decrease");
    if (!(words >> event.action)) Fail(where, "missing the action after the time");
    if (event.action == "drag" || event.action == "pan") {
      if (!(words >> event.x >> event.y)) Fail(where, event.action, " needs DX DY in pixels");
    } else if (event.action == "scroll") {
      if (!(words >> event.y)) Fail(where, "scroll needs STEPS");
    } else if (event.action == "key") {
      if (!(words >> event.key)) Fail(where, "key needs a key (T, L, R, 0-9, W, A, S, D, F12)");
    } else if (event.action != "screenshot" && event.action != "quit") {
      Fail(where, "unknown action '", event.action, "' (expected drag, pan, scroll, key, screenshot or quit)");
    }
    std::string extra;
    if (words >> extra) Fail(where, "unexpected '", extra, "' after the ", event.action);
    events.push_back(event);
  }
  return events;
}

std::vector<ViewerEvent> ReadViewerScript(const std::filesystem::path& file) {
  if (!std::filesystem::is_regular_file(file)) Fail(file.string(), ": script file not found");
  return ParseViewerScript(ReadFile(file), file.string());
}

}  // namespace voltree
