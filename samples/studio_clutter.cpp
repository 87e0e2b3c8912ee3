#include "samples/studio_clutter.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "samples/tree_random.h"

namespace voltree {

ClutterLayout MakeStudioClutter(uint64_t seed, const Eigen::Vector2d& centre, double tree_height, double clear_radius) {
  TreeRandom random(HashCombine(seed, 0xC1077E5ull));
  ClutterLayout layout;
  layout.wall_radius = 4 * clear_radius;
  const double h = std::max(tree_height, 1e-3);
  auto place = [&](double near, double far, double size) {
    // Uniform over the annulus's area, kept clear of the ring by the object's own size.
    const double r_lo = near + size, r_hi = std::max(far, r_lo);
    const double r = std::sqrt(r_lo * r_lo + (r_hi * r_hi - r_lo * r_lo) * random.Uniform());
    const double azimuth = 2 * std::numbers::pi * random.Uniform();
    return Eigen::Vector2d(centre + r * Eigen::Vector2d(std::cos(azimuth), std::sin(azimuth)));
  };
  for (int i = 0; i < 28; ++i) {  // bushes: half-buried ellipsoids, 6-20 % of the tree's height
    ClutterObject bush;
    bush.kind = ClutterObject::kBush;
    bush.radius = h * random.Uniform(0.06f, 0.2f);
    bush.vertical_radius = bush.radius * random.Uniform(0.6f, 1.0f);
    bush.centre << place(clear_radius, 2.5 * clear_radius, bush.radius), 0.3 * bush.vertical_radius;
    bush.tint = random.Uniform();
    layout.objects.push_back(bush);
  }
  for (int i = 0; i < 16; ++i) {  // rocks: flat, mostly small
    ClutterObject rock;
    rock.kind = ClutterObject::kRock;
    rock.radius = h * random.Uniform(0.02f, 0.08f);
    rock.vertical_radius = rock.radius * random.Uniform(0.35f, 0.7f);
    rock.centre << place(clear_radius, 2.0 * clear_radius, rock.radius), 0.0;
    rock.tint = random.Uniform();
    layout.objects.push_back(rock);
  }
  for (int i = 0; i < 24; ++i) {  // other trees at a distance: crowns on trunks
    ClutterObject tree;
    tree.kind = ClutterObject::kTree;
    const double height = h * random.Uniform(0.6f, 1.4f);
    tree.radius = height * random.Uniform(0.22f, 0.35f);
    tree.vertical_radius = height * random.Uniform(0.3f, 0.4f);
    tree.trunk_radius = height * 0.025;
    tree.centre << place(1.3 * clear_radius, 3.5 * clear_radius, tree.radius), height - tree.vertical_radius;
    tree.tint = random.Uniform();
    layout.objects.push_back(tree);
  }
  return layout;
}

}  // namespace voltree
