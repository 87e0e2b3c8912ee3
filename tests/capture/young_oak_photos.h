// The studio's photos of a young oak and their true mattes, for the matting tests.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "capture/colmap_binary.h"
#include "core/camera.h"
#include "core/error.h"
#include "core/image.h"
#include "pipeline/voltree_binary.h"
#include "temp_dir.h"

namespace voltree::test {

struct YoungOakPhotos {
  std::vector<View> views;
  std::vector<Image8> photos, truth;
};

// 16 photos, no held-out views, at `size`² (192²: about a second), with `extra` on synth's
// command line; empty when the studio fails.
inline YoungOakPhotos PhotographYoungOak(const std::string& extra, int size = 192) {
  // The process id as well: a suite photographs its set before any of its tests runs.
  const std::filesystem::path dir = voltree::testing::FreshFolder(Str("young_oak_", ::getpid()));
  YoungOakPhotos set;
  if (Voltree(Str("synth --tree young-oak --views 16 --held-out 0 --size ", size, " --quiet --force ", extra) + " -o " +
              dir.string()) != 0)
    return set;
  set.views = ReadColmapModel(dir / "sparse").Views();
  for (const View& view : set.views) {
    set.photos.push_back(ReadImage8(dir / "images" / view.name, 3));
    set.truth.push_back(ReadImage8(dir / "mattes" / (std::filesystem::path(view.name).stem().string() + ".png"), 1));
  }
  std::filesystem::remove_all(dir);
  return set;
}

}  // namespace voltree::test
