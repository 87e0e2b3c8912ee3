// Which fraction of the leaves a tree drawn `size` pixels tall keeps. Neubert et al. 2011 (sec. 3)
// quote Cook et al.'s rule lambda(d) = (1 - d)^2 with the distance d normalized to [0, 1]; with the
// normalized distance taken as d = 1 - size / full_size (the tree shrinks on screen as it moves
// away) this is lambda = (size / full_size)^2: the kept leaves are proportional to the tree's
// screen area. `min_lambda` keeps a few leaves on the smallest trees.
#pragma once

namespace voltree {

// Throws Error when size or full_size is not positive, or size > full_size.
double LambdaForScreenSize(double size, double full_size, double min_lambda);

}  // namespace voltree
