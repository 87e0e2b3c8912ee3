// `voltree matte`: mattes and premultiplied foregrounds for every photo of a capture workspace,
// computed (MatteImage) or taken from the user's own mattes.
//   DIR/images/NAME.ext -> DIR/mattes/NAME.png (8-bit grey) + DIR/foreground/NAME.png (RGBA,
//   premultiplied colour).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "capture/matte/coverage.h"
#include "capture/matte/options.h"
#include "core/progress.h"

namespace voltree {

struct MatteWorkspaceOptions {
  MatteOptions matte;
  // A folder of the user's mattes (PNG alpha or grey, same stems as the photos); empty: compute.
  std::filesystem::path user_mattes;
  // Mattes outside these limits stop the stage (nothing is written) with the photos named.
  MatteCoverageLimits coverage;
  bool force = false;  // replace existing DIR/mattes and DIR/foreground
  int threads = 0;     // 0: all cores
  void Check() const;
};

// The user's matte for `photo` in `mattes_dir`: the file with the photo's stem and an image
// extension. Throws Error naming the expected file and the photo when there is none.
std::filesystem::path FindUserMatte(const std::filesystem::path& mattes_dir, const std::filesystem::path& photo);

// Throws Error naming both files and both sizes when `matte` and `photo` differ in size.
void CheckMatteSize(const std::filesystem::path& matte, const std::filesystem::path& photo);

// Writes DIR/mattes and DIR/foreground (each built aside and moved into place whole). Throws
// Error before any work when they exist and `force` is off, and after the work, writing nothing,
// when a matte covers too much or too little of its photo (options.coverage). Returns the number
// of photos.
size_t MatteWorkspace(const std::filesystem::path& dir, const MatteWorkspaceOptions& options, Progress& progress);

}  // namespace voltree
