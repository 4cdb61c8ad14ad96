// ValenceChanges (valence_changes.h) behaves as the std::map<int, int> it replaces in
// AtomicOperations (Candidates, predictions, outcomes): same order, same insert, operator[],
// find and erase semantics, inline up to kInline entries and on the heap beyond.
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
    // keys from a range wider than the inline room, so that maps cross it both ways
    for (int k = 0; k < 40; ++k) {
      const int key = int(rng() % 21) - 1, value = int(rng() % 10);
      switch (rng() % 4) {
        case 0: EXPECT_EQ(c.Insert(key, value), m.insert({key, value}).second); break;
        case 1:
          c[key] = value;
          m[key] = value;
          break;
        case 2: {
          auto it = m.find(key);
          auto ct = c.find(key);
          ASSERT_EQ(ct == c.end(), it == m.end());
          if (it != m.end()) EXPECT_EQ(ct->second, it->second);
          break;
        }
        default:
          c.erase(key);
          m.erase(key);
      }
      ASSERT_EQ(c.ToMap(), m) << "round " << round << " op " << k;
      ASSERT_EQ(c.size(), m.size());
      const ValenceChanges copy = c;  // copies compare equal, entry by entry
      ASSERT_TRUE(copy == c);
    }
  }
}

TEST(ValenceChanges, GrowsPastItsInlineRoomInOrder) {
  ValenceChanges c;
  const int n = int(ValenceChanges::kInline) * 3;
  for (int k = n - 1; k >= 0; --k) EXPECT_TRUE(c.Insert(2 * k, k));  // descending: every insert shifts
  EXPECT_FALSE(c.Insert(0, 5));  // a key already in keeps its value
  ASSERT_EQ(c.size(), size_t(n));
  int expect = 0;
  for (auto& kv : c) {
    EXPECT_EQ(kv.first, 2 * expect);
    EXPECT_EQ(kv.second, expect);
    ++expect;
  }
  ValenceChanges moved = std::move(c);
  EXPECT_EQ(moved.size(), size_t(n));
  EXPECT_EQ(moved.at(2 * (n - 1)), n - 1);
  ValenceChanges other = {{1, 5}};
  EXPECT_FALSE(other == moved);
  other = moved;
  EXPECT_TRUE(other == moved);
  other[1] = 7;  // a new key in the middle
  EXPECT_EQ(other.size(), size_t(n) + 1);
  EXPECT_EQ(other.at(1), 7);
  EXPECT_FALSE(other == moved);
}
