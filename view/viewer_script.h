// A scripted session for `voltree view --script FILE` (tests, demos): one event a line,
//   SECONDS ACTION [ARGS]     e.g.  0.5 drag 40 -10   |  1 key T  |  1.2 screenshot  |  2 quit
// ACTION: drag DX DY (turn, pixels), pan DX DY, scroll STEPS, key K (a key as typed: T, L, V, R,
// 0-9, W, A, S, D, P), screenshot, quit. '#' starts a comment. Times are seconds from the first frame,
// non-decreasing; events run in order once their time has come, and a screenshot holds the
// events after it until it is taken (once the LOD choice at its camera has settled).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace voltree {

struct ViewerEvent {
  double seconds = 0;
  std::string action;  // drag, pan, scroll, key, screenshot, quit
  double x = 0, y = 0;
  std::string key;
};

// Throws Error naming the file, the line and what was expected.
std::vector<ViewerEvent> ParseViewerScript(std::string_view text, const std::string& name);
std::vector<ViewerEvent> ReadViewerScript(const std::filesystem::path& file);

}  // namespace voltree
