// Matting, the public face: what the rest of voltree uses of capture/matte/. Mattes and
// foreground colours for a workspace (workspace.h), their options (options.h), one photo at a
// time (image.h), the checks that stop a run on bad mattes (coverage.h, consistency.h), matting
// again inside the visual hull of the others (hull_refine.h), and the metrics against a true
// matte (metrics.h).
#pragma once

#include "capture/matte/consistency.h"
#include "capture/matte/coverage.h"
#include "capture/matte/hull_refine.h"
#include "capture/matte/image.h"
#include "capture/matte/metrics.h"
#include "capture/matte/options.h"
#include "capture/matte/workspace.h"
