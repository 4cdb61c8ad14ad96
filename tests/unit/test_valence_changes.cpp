// ValenceChanges (valence_changes.h) behaves as the std::map<int, int> it replaces in
// AtomicOperations::Candidates: same order, same insert and operator[] semantics.
#include <gtest/gtest.h>

#include <map>
#include <random>
#include <stdexcept>

#include <vcg_ext/irregular/valence_changes.h>

using vcg_ext::irregular::ValenceChanges;

TEST(ValenceChanges, ListAssignmentKeepsTheFirstValueOfARepeatedKeyAndSortsAsAMap) {
  ValenceChanges c = {{40, 7}, {12, 5}, {40, 3}, {-1, 4}};
  std::map<int, int> m = {{40, 7}, {12, 5}, {40, 3}, {-1, 4}};
  EXPECT_EQ(c.ToMap(), m);
  EXPECT_EQ(c.size(), 3u);
  EXPECT_EQ(c.begin()->first, -1);
  EXPECT_EQ(c.at(40), 7);
  EXPECT_EQ(c.count(12), 1u);
  EXPECT_EQ(c.count(13), 0u);
  EXPECT_THROW(c.at(13), std::out_of_range);
  c = {{3, 6}};  // reassignment forgets the old entries
  EXPECT_EQ(c.ToMap(), (std::map<int, int>{{3, 6}}));
}

TEST(ValenceChanges, SplitRenamingAsCandidatesDoesIt) {
  // Candidates predicts a split's new vertex under key -1, then renames it to its index
  ValenceChanges pred = {{8, 5}, {-1, 4}, {2, 7}, {9, 6}};
  const int created = 100;
  pred[created] = pred[-1];
  pred.erase(-1);
  EXPECT_EQ(pred.ToMap(), (std::map<int, int>{{2, 7}, {8, 5}, {9, 6}, {100, 4}}));
  pred.erase(55);  // absent: nothing happens
  EXPECT_EQ(pred.size(), 4u);
}

TEST(ValenceChanges, RandomOperationsMatchStdMap) {
  std::mt19937 rng(7);
  for (int round = 0; round < 2000; ++round) {
    ValenceChanges c;
    std::map<int, int> m;
    for (int k = 0; k < 12; ++k) {
      const int key = int(rng() % 9) - 1, value = int(rng() % 10);
      switch (rng() % 3) {
        case 0:
          if (m.size() < ValenceChanges::kCapacity || m.count(key)) EXPECT_EQ(c.Insert(key, value), m.insert({key, value}).second);
          break;
        case 1:
          if (m.size() < ValenceChanges::kCapacity || m.count(key)) {
            c[key] = value;
            m[key] = value;
          }
          break;
        default:
          c.erase(key);
          m.erase(key);
      }
      ASSERT_EQ(c.ToMap(), m) << "round " << round << " op " << k;
    }
  }
}

TEST(ValenceChanges, RefusesAnEntryPastItsCapacity) {
  ValenceChanges c;
  for (int k = 0; k < int(ValenceChanges::kCapacity); ++k) c.Insert(k, 6);
  EXPECT_THROW(c.Insert(99, 5), std::length_error);
  EXPECT_FALSE(c.Insert(0, 5));  // a key already in needs no room
}
