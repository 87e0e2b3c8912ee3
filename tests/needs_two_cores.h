// Thread-determinism tests compare a 1-thread run with a multi-threaded one; on a one-core
// machine both run on one core and the comparison proves nothing, so they are skipped there
// with a message instead of passing vacuously.
#pragma once

#include <gtest/gtest.h>

#include <thread>

#define VOLTREE_SKIP_UNLESS_TWO_CORES()                                                                       \
  if (std::thread::hardware_concurrency() < 2)                                                                \
  GTEST_SKIP() << "needs 2 or more cores to compare threaded with single-threaded results (this machine has " \
               << std::thread::hardware_concurrency() << ")"
