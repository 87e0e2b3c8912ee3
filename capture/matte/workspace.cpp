#include "capture/matte/workspace.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <map>
#include <memory>
#include <optional>

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include "capture/matte/foreground.h"
#include "capture/matte/image.h"
#include "capture/photo_folder.h"
#include "core/error.h"
#include "core/files.h"
#include "core/image.h"

namespace voltree {
namespace fs = std::filesystem;

namespace {

// One photo: its matte (computed or the user's) and its premultiplied foreground.
struct MatteOutputs {
  Image8 alpha, foreground;
  double coverage = 0;
  std::string summary;
};

MatteOutputs MatteOnePhoto(const fs::path& photo_path, const MatteWorkspaceOptions& options) {
  const Image8 photo = ReadImage8(photo_path, 3);
  MatteOutputs out;
  if (options.user_mattes.empty()) {
    MatteResult result = MatteImage(photo, options.matte);
    out.alpha = std::move(result.alpha);
    out.foreground = std::move(result.foreground);
    out.summary = Str("horizon at row ", result.horizon_row, " of ", photo.height);
  } else {
    const fs::path matte_path = FindUserMatte(options.user_mattes, photo_path);
    out.alpha = ReadImage8(matte_path, 1);
    if (out.alpha.width != photo.width || out.alpha.height != photo.height)
      Fail(matte_path.string(), ": matte is ", out.alpha.width, "x", out.alpha.height, " but its photo ",
           photo_path.string(), " is ", photo.width, "x", photo.height);
    out.foreground = PremultipliedForeground(photo, out.alpha);
    out.summary = Str("matte from ", matte_path.string());
  }
  out.coverage = MatteCoverage(out.alpha);
  out.summary += Str(", ", int(std::lround(100.0 * out.coverage)), "% covered");
  return out;
}

}  // namespace

void MatteWorkspaceOptions::Check() const {
  matte.Check();
  coverage.Check();
  if (threads < 0) FailOption("MatteWorkspaceOptions.threads", "must be 0 (all cores) or positive, got ", threads);
  if (!user_mattes.empty() && !fs::is_directory(user_mattes))
    Fail(user_mattes.string(), ": --mattes expects a folder of mattes named like the photos");
}

fs::path FindUserMatte(const fs::path& mattes_dir, const fs::path& photo) {
  const std::string stem = photo.stem().string();
  for (const char* extension : kPhotoExtensions) {
    std::string upper = extension;
    std::transform(upper.begin(), upper.end(), upper.begin(), [](unsigned char c) { return char(std::toupper(c)); });
    for (const std::string& candidate : {stem + extension, stem + upper})
      if (fs::is_regular_file(mattes_dir / candidate)) return mattes_dir / candidate;
  }
  Fail((mattes_dir / (stem + ".png")).string(), ": missing matte for photo ", photo.string());
}

void CheckMatteSize(const fs::path& matte, const fs::path& photo) {
  const auto [mw, mh] = ReadImageSize(matte);
  const auto [pw, ph] = ReadImageSize(photo);
  if (mw != pw || mh != ph)
    Fail(matte.string(), ": matte is ", mw, "x", mh, " but its photo ", photo.string(), " is ", pw, "x", ph);
}

size_t MatteWorkspace(const fs::path& dir, const MatteWorkspaceOptions& options, Progress& progress) {
  options.Check();
  const std::vector<fs::path> photos = ListPhotos(dir / "images");
  CheckPhotoSizes(photos);
  // Check the user's mattes before any work, so a bad one fails fast.
  if (!options.user_mattes.empty())
    for (const fs::path& photo : photos) CheckMatteSize(FindUserMatte(options.user_mattes, photo), photo);
  StagedDirectory mattes(dir / "mattes", options.force);
  StagedDirectory foreground(dir / "foreground", options.force);

  std::optional<tbb::global_control> limit;
  if (options.threads > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, size_t(options.threads));
  std::atomic<size_t> done{0};
  std::vector<NamedCoverage> coverages(photos.size());
  progress.Say("matte", Str(photos.size(), " photos in ", (dir / "images").string(),
                            options.user_mattes.empty() ? Str(", refine ", RefineMethodName(options.matte.refine))
                                                        : Str(", mattes from ", options.user_mattes.string())));
  // Each photo is independent and written to its own files: the order threads take them in does
  // not change any output.
  tbb::parallel_for(size_t(0), photos.size(), [&](size_t i) {
    const MatteOutputs out = MatteOnePhoto(photos[i], options);
    const std::string name = photos[i].stem().string() + ".png";
    WriteImage(mattes.path() / name, out.alpha);
    WriteImage(foreground.path() / name, out.foreground);
    coverages[i] = {photos[i].filename().string(), out.coverage};
    progress.Say("matte", Str(++done, "/", photos.size(), " ", photos[i].filename().string(), ": ", out.summary));
  });
  CheckMatteCoverage(coverages, options.coverage,
                     options.user_mattes.empty() ? "computed" : Str("from ", options.user_mattes.string()),
                     options.user_mattes.empty());
  mattes.Commit();
  foreground.Commit();
  return photos.size();
}

}  // namespace voltree
