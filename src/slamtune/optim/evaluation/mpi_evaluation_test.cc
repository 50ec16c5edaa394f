#include "slamtune/optim/evaluation/mpi_evaluation.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace slamtune::optim {
namespace {

// The distributed path itself runs under mpirun in tests/mpi_cli_test.sh; here, the world a
// plain process sees.
TEST(MpiWorld, OutsideMpirunIsOneRank) {
  if (MpiWorld::LaunchedByMpirun()) GTEST_SKIP() << "running under mpirun";
  MpiWorld world;
  EXPECT_EQ(world.rank(), 0);
  EXPECT_EQ(world.size(), 1);
  EXPECT_FALSE(world.distributed());
}

TEST(MpiWorld, BuiltMatchesTheBuildOption) {
#ifdef SLAMTUNE_HAVE_MPI
  EXPECT_TRUE(MpiWorld::Built());
#else
  EXPECT_FALSE(MpiWorld::Built());
#endif
}

}  // namespace
}  // namespace slamtune::optim
