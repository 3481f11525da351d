// Independent simulations side by side on groups of ranks (dem/ensemble.h), under
// mpirun -np 3: the groups the ranks are cut into (sizes worked out by hand for three ranks),
// every member's result on every rank as its group made it, a failure in one group failing
// every rank with its message, and a group's share of the machine's cores.
#include <abrade/common/error.h>
#include <abrade/dem/ensemble.h>

#include <gtest/gtest.h>

#include <map>
#include <stdexcept>

using namespace abrade;
using namespace abrade::dem;

namespace
{
  /// The size of each member's group, as every rank sees it (gathered over the world).
  std::vector<int> group_sizes_of_members(const Ensemble &e, std::size_t members)
  {
    std::vector<double> size(members, 0.0);
    for (std::size_t m = 0; m < members; ++m)
      if (e.runs(m))
        size[m] = e.group().size();
    Parallel::world().max(size); // every rank of the group says the same
    return std::vector<int>(size.begin(), size.end());
  }
} // namespace

TEST(Ensemble, CutsThreeRanksIntoGroupsOfTheWork)
{
  const Parallel world = Parallel::world();
  ASSERT_EQ(world.size(), 3) << "run under mpirun -np 3";
  // (members, ranks per member) -> the size of the group of member 0, 1, ...
  const std::vector<std::tuple<std::size_t, int, std::vector<int>>> cases = {
    {1, 0, {3}},             // one bed: all ranks
    {2, 0, {2, 1}},          // two beds: ranks 0-1 and rank 2
    {3, 0, {1, 1, 1}},       // one rank each
    {5, 0, {1, 1, 1, 1, 1}}, // more beds than ranks: members 0 and 3 on rank 0, ...
    {3, 2, {3, 3, 3}},       // groups of about 2 among 3 ranks: one group
    {3, 1, {1, 1, 1}},
    {2, 5, {3, 3}}};         // more ranks per bed than there are: all, one bed after another
  for (const auto &[members, per_member, expected] : cases)
    {
      const Ensemble e(world, members, per_member);
      EXPECT_EQ(group_sizes_of_members(e, members), expected) << members << " members, " << per_member << " per member";
      // every member run by exactly one group: its ranks
      for (std::size_t m = 0; m < members; ++m)
        EXPECT_EQ(world.sum(long(e.runs(m))), expected[m]) << "member " << m;
      // the groups share the machine's cores: each counts the world's ranks
      EXPECT_EQ(e.group().ranks_on_this_machine(), world.ranks_on_this_machine());
    }
}

TEST(Ensemble, SharesEachMembersResultFromItsGroup)
{
  const Parallel world = Parallel::world();
  const Ensemble e(world, 5, 0); // 3 groups of one: members 0, 3 on rank 0; 1, 4 on rank 1; 2 on rank 2
  std::vector<std::vector<double>> result(5);
  std::vector<std::string>         text(5);
  for (std::size_t m = 0; m < 5; ++m)
    if (e.runs(m))
      {
        result[m] = std::vector<double>(m + 1, 100.0 * m + world.rank()); // lengths differ
        text[m]   = "member " + std::to_string(m) + " from rank " + std::to_string(world.rank());
      }
  for (std::size_t m = 0; m < 5; ++m)
    {
      e.share(result[m], m);
      e.share(text[m], m);
    }
  const int rank_of[] = {0, 1, 2, 0, 1};
  for (std::size_t m = 0; m < 5; ++m)
    {
      EXPECT_EQ(result[m], std::vector<double>(m + 1, 100.0 * m + rank_of[m])) << "member " << m;
      EXPECT_EQ(text[m], "member " + std::to_string(m) + " from rank " + std::to_string(rank_of[m]));
    }
  // groups of two and one: member 1's result comes from rank 2, the first (and only) of its group
  const Ensemble      uneven(world, 2, 0);
  std::vector<double> second;
  if (uneven.runs(1))
    second = {2.0 + world.rank()};
  uneven.share(second, 1);
  EXPECT_EQ(second, std::vector<double>{4.0});
}

TEST(Ensemble, AGroupsFailureFailsEveryRank)
{
  const Parallel world = Parallel::world();
  const Ensemble e(world, 2, 0); // ranks 0-1 run member 0, rank 2 member 1
  // nothing failed: nothing thrown
  EXPECT_NO_THROW(e.fail_together(nullptr));
  // member 1's group fails with a run error: every rank throws it, with its message
  std::exception_ptr failure;
  if (e.runs(1))
    failure = std::make_exception_ptr(RunError("bed 2: NaN in the particle velocities"));
  try
    {
      e.fail_together(failure);
      ADD_FAILURE() << "no exception on rank " << world.rank();
    }
  catch (const RunError &x)
    {
      EXPECT_STREQ(x.what(), "bed 2: NaN in the particle velocities");
    }
  // both groups fail: the lowest rank's failure (an input error) wins everywhere
  failure = e.runs(0) ? std::make_exception_ptr(InputError("bed-seed1.bed", "corrupt bed file"))
                      : std::make_exception_ptr(std::runtime_error("something else"));
  try
    {
      e.fail_together(failure);
      ADD_FAILURE() << "no exception on rank " << world.rank();
    }
  catch (const InputError &x)
    {
      EXPECT_STREQ(x.what(), "bed-seed1.bed: corrupt bed file");
    }
}

int main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  if (Parallel::world().rank() != 0) // one report
    delete ::testing::UnitTest::GetInstance()->listeners().Release(
      ::testing::UnitTest::GetInstance()->listeners().default_result_printer());
  const int result = RUN_ALL_TESTS();
  MPI_Finalize();
  return result;
}
