#include "pipeline/evaluation_renders.h"

#include <tbb/task_group.h>

#include <algorithm>
#include <array>
#include <memory>

#include "core/error.h"
#include "core/image.h"
#include "pipeline/comparison_images.h"
#include "pipeline/report_folder.h"

namespace voltree {
namespace fs = std::filesystem;

namespace {

// One view's renders. The metrics are filled in by worker tasks: the object stays where it is
// (behind a unique_ptr) until they are waited for.
struct ViewEvaluation {
  std::vector<ViewMetrics> per_choice;
  std::optional<ComparisonFiles> comparison;
  double render_seconds = 0;
};

ComparisonFiles ComparisonFilesOf(const std::string& view_name) {
  const std::string stem = Str(kEvalFolderName, "/held_out/", FlatStem(view_name));
  ComparisonFiles files;
  files.view = view_name;
  files.truth = stem + "_truth.png";
  files.render = stem + "_voltree.png";
  files.difference = stem + "_difference.png";
  return files;
}

void WriteComparison(const Image8& truth, const Image8& render, const ImageMetricsOptions& metrics,
                     const std::string& view_name, const EvaluationRenderSettings& settings) {
  const Image8 truth_rgb = CompositeForDisplay(truth, metrics.background_grey, metrics.truth_premultiplied);
  const Image8 render_rgb = CompositeForDisplay(render, metrics.background_grey, false);
  const fs::path folder = settings.staging / "held_out";
  const std::string stem = FlatStem(view_name);
  WriteImage(folder / (stem + "_truth.png"), truth_rgb);
  WriteImage(folder / (stem + "_voltree.png"), render_rgb);
  WriteImage(folder / (stem + "_difference.png"), AmplifiedDifference(truth_rgb, render_rgb, settings.difference_gain));
}

// Renders one view at every level choice; the comparisons (and the images of a held-out view at
// the auto LOD) run as tasks of `compare`.
std::unique_ptr<ViewEvaluation> RenderView(const TruthView& view, ViewSet set, const EvaluationRenderSettings& settings,
                                           TreeRenderer& renderer, tbb::task_group& compare, Progress& progress) {
  auto result = std::make_unique<ViewEvaluation>();
  auto truth = std::make_shared<const Image8>(LoadTruthImage(view));
  ImageMetricsOptions metrics = settings.metrics;
  metrics.truth_premultiplied = view.premultiplied;
  metrics.render_premultiplied = false;  // TreeRenderer::Render returns straight alpha
  result->per_choice.resize(settings.choices.size());
  for (size_t c = 0; c < settings.choices.size(); ++c) {
    TreeRenderOptions render_options;
    render_options.lod = settings.lod;
    render_options.lod.forced_level = settings.choices[c].forced_level;
    render_options.lod_history = false;  // every view judged on its own, independent of the order
    const double start = progress.ElapsedSeconds();
    auto render = std::make_shared<const Image8>(renderer.Render(view.camera, render_options));
    result->render_seconds += progress.ElapsedSeconds() - start;
    const bool write_images = settings.images && set == ViewSet::kHeldOut && settings.choices[c].IsAuto();
    if (write_images) result->comparison = ComparisonFilesOf(view.camera.name);
    compare.run([=, &settings, &view, out = &result->per_choice[c]] {
      *out = CompareViews(*render, *truth, metrics);
      if (write_images) WriteComparison(*truth, *render, metrics, view.camera.name, settings);
    });
  }
  return result;
}

}  // namespace

std::string FlatStem(const std::string& view_name) {
  std::string stem = fs::path(view_name).replace_extension().string();
  std::replace(stem.begin(), stem.end(), '/', '_');
  return stem;
}

EvaluationRenders RenderAndCompare(const std::vector<TruthView>& held_out, const std::vector<TruthView>& inputs,
                                   const EvaluationRenderSettings& settings, TreeRenderer& renderer,
                                   Progress& progress) {
  const std::array<std::pair<ViewSet, const std::vector<TruthView>*>, 2> sets = {
      std::pair{ViewSet::kHeldOut, &held_out}, std::pair{ViewSet::kInput, &inputs}};
  std::array<std::vector<std::unique_ptr<ViewEvaluation>>, 2> views;
  {
    // Two groups in turn: a view's comparisons overlap the next view's renders, and at most two
    // views' images are in memory at once.
    std::array<tbb::task_group, 2> compare;
    size_t turn = 0;
    for (size_t s = 0; s < sets.size(); ++s) {
      const auto& [set, truth] = sets[s];
      for (size_t v = 0; v < truth->size(); ++v, ++turn) {
        compare[turn % 2].wait();
        views[s].push_back(RenderView((*truth)[v], set, settings, renderer, compare[turn % 2], progress));
        progress.Say("eval", Str(ViewSetName(set), " ", (*truth)[v].camera.name, " ", v + 1, "/", truth->size()));
      }
    }
    compare[0].wait();
    compare[1].wait();
  }
  EvaluationRenders renders;
  renders.table = LevelMetricsTable(settings.choices);
  for (size_t s = 0; s < sets.size(); ++s) {
    for (size_t v = 0; v < views[s].size(); ++v) {
      const ViewEvaluation& view = *views[s][v];
      for (size_t c = 0; c < settings.choices.size(); ++c)
        renders.table.Add(settings.choices[c], sets[s].first, (*sets[s].second)[v].camera.name, view.per_choice[c]);
      if (view.comparison) renders.comparisons.push_back(*view.comparison);
      renders.render_seconds += view.render_seconds;
    }
  }
  return renders;
}

}  // namespace voltree
