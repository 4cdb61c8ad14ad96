// Helpers for the composite-operation tests: irregular vertices by index, and an adjacent
// 5-7 pair parked away with the atomic moves (atomic_ops.h, fig. 6) only.
#pragma once

#include <algorithm>
#include <map>
#include <vector>

#include <gtest/gtest.h>

#include <vcg_ext/irregular/atomic_ops.h>

#include "test_mesh.h"

namespace test {
typedef vcg::Point3f P3;
using vcg_ext::irregular::AtomicOperations;
using vcg_ext::irregular::AtomicOutcome;
using vcg_ext::irregular::MeshEditor;
using vcg_ext::irregular::ComputeValences;

/// vertex -> valence of every irregular vertex (interior != 6, boundary != 4).
inline std::map<int, int> Irregular(TMesh& m) {
  std::map<int, int> r;
  auto vf = ComputeValences(m);
  for (size_t i = 0; i < m.vert.size(); ++i)
    if (!m.vert[i].IsD() && vf.referenced[i] && vf.IsIrregular(i)) r[int(i)] = vf.valence[i];
  return r;
}

/// Moves the adjacent 5-7 pair (p5, p7) `steps` atomic steps (atomic_ops.h, fig. 6), each the
/// move that takes its midpoint furthest from the points `away`.
inline void Park(MeshEditor<TMesh>& ed, AtomicOperations<TMesh>& ops, int& p5, int& p7, const std::vector<P3>& away,
          int steps) {
  auto far = [&](int a, int b) {
    const P3 mid = (ed.V(a)->P() + ed.V(b)->P()) / 2;
    float d = 1e9f;
    for (const P3& p : away) d = std::min(d, (mid - p).Norm());
    return d;
  };
  for (int s = 0; s < steps; ++s) {
    int best = -1;
    float bestD = far(p5, p7);
    for (int dir = 0; dir < 6; ++dir) {
      auto cp = ed.Mark();
      AtomicOutcome o = ops.MovePair57(p5, p7, dir);
      if (o && far(o.irregular[0], o.irregular[1]) > bestD + 1e-4f) bestD = far(o.irregular[0], o.irregular[1]), best = dir;
      ed.RollbackTo(cp);
    }
    ASSERT_GE(best, 0) << "the pair cannot be parked further";
    AtomicOutcome o = ops.MovePair57(p5, p7, best);
    ASSERT_TRUE(o);
    p5 = o.irregular[0];
    p7 = o.irregular[1];
  }
}

}  // namespace test
