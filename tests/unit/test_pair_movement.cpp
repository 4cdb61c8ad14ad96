// Unit tests of the pair movement of sec. 7.1 (vcg_ext/irregular/composite_ops.h): where the
// two vertices of a pair end up, on a planar lattice patch whose vertices sit at lattice
// points (relaxation off, so a vertex that only changes valence keeps its lattice position).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <vcg_ext/irregular/composite_ops.h>
#include <vcg_ext/irregular/mesh_checks.h>
#include <vcg_ext/irregular/separatrix.h>

#include "test_mesh.h"
#include "test_util.h"
#include "test_boundary_mesh.h"
#include "composite_test_util.h"

using namespace vcg_ext::irregular;
using test::TMesh;

namespace {
using test::Irregular;
using test::Park;
typedef vcg::Point3f P3;

/// A planar hexagonal patch (radius 14, unit edges) holding a non-adjacent 5-7 pair (v5, v7)
/// `separation` edges apart near the centre; every other irregular interior vertex (the
/// pairs generated while building it) is parked at least 6 edges away. Built with the atomic
/// operations only (fig. 6, 7), which the composite operations under test build on.
struct SeparatedPair {
  TMesh m;
  int v5 = -1, v7 = -1;
  void Build(int separation) {
    test::HexPatch(m, 14);
    GeometryOptions g;
    g.checkFolds = false;
    MeshEditor<TMesh> ed(m, g);
    AtomicOperations<TMesh> ops(ed);
    const int n = ed.Index(ed.Star(0).neighbors[0]);
    int o[2];
    ASSERT_TRUE(ed.Opposites(0, n, o));
    ASSERT_TRUE(ed.Flip(0, n).ok);  // 0, n -> v5; o0, o1 -> v7
    int b5 = n, b7 = o[1];
    Park(ed, ops, b5, b7, {m.vert[0].P()}, 7);
    v5 = 0;
    v7 = o[0];
    // separate the v5 from its v7: move it one step away with pair generation (fig. 7) and
    // park the generated pair, `separation - 1` times
    for (int s = 1; s < separation; ++s) {
      int bestK = -1;
      float bestD = -1;
      for (int k = 0; k < 5; ++k) {
        auto cp = ed.Mark();
        AtomicOutcome g = ops.MoveWithPairGeneration(v5, k);
        if (g) {
          const float d = (m.vert[size_t(g.irregular[0])].P() - m.vert[size_t(v7)].P()).Norm();
          if (d > bestD) bestD = d, bestK = k;
        }
        ed.RollbackTo(cp);
      }
      ASSERT_GE(bestK, 0);
      AtomicOutcome g = ops.MoveWithPairGeneration(v5, bestK);
      ASSERT_TRUE(g);
      v5 = g.irregular[0];
      int g5 = g.irregular[1], g7 = g.irregular[2];
      if (ed.Valence(g5) != 5) std::swap(g5, g7);
      const P3 bmid = (m.vert[size_t(b5)].P() + m.vert[size_t(b7)].P()) / 2;
      Park(ed, ops, g5, g7, {m.vert[size_t(v5)].P(), m.vert[size_t(v7)].P(), bmid}, 7);
    }
    ASSERT_EQ(ed.Valence(v5), 5);
    ASSERT_EQ(ed.Valence(v7), 7);
    ASSERT_FALSE(ed.Adjacent(v5, v7));
    ed.Commit();
  }
};

/// The planar patch keeps its lattice positions (no relaxation), where a few flips in a row
/// make collinear triangles: these tests are about connectivity, so the fold check is off.
GeometryOptions Combinatorial() {
  GeometryOptions g;
  g.checkFolds = false;
  return g;
}

/// The neighbourhood of radius r around vertex `root`, labelled canonically from the directed
/// edge (root, first): vertices are numbered in breadth-first order, each vertex's neighbours
/// taken counter-clockwise from its lowest-numbered neighbour. Two such forms are equal iff
/// an orientation-preserving isomorphism maps one rooted neighbourhood onto the other: the
/// irregular vertices sit at the same places relative to the root edge.
std::vector<std::vector<int>> CanonicalNeighbourhood(TMesh& m, int root, int first, int r) {
  std::map<int, int> label{{root, 0}, {first, 1}};
  std::vector<int> order{root, first}, depth{0, 1};
  std::vector<std::vector<int>> form;
  for (size_t q = 0; q < order.size(); ++q) {
    const int v = order[q];
    VertexStar<TMesh> st = StarOf<TMesh>(&m.vert[size_t(v)]);
    std::vector<int> nb;
    for (auto* n : st.neighbors) nb.push_back(int(vcg::tri::Index(m, n)));
    // start at the lowest-labelled neighbour (the one v was reached from, for v != root)
    size_t start = 0;
    int bestLabel = 1 << 30;
    for (size_t i = 0; i < nb.size(); ++i)
      if (label.count(nb[i]) && label[nb[i]] < bestLabel) bestLabel = label[nb[i]], start = i;
    std::vector<int> row{int(nb.size())};
    for (size_t i = 0; i < nb.size(); ++i) {
      const int w = nb[(start + i) % nb.size()];
      if (!label.count(w) && depth[q] < r) {
        label[w] = int(order.size());
        order.push_back(w);
        depth.push_back(depth[q] + 1);
      }
      row.push_back(label.count(w) ? label[w] : -1);
    }
    if (depth[q] < r) form.push_back(row);
  }
  return form;
}

/// The first vertex after `a` on the connecting path from a to b (separatrix.h).
int FirstOnPath(TMesh& m, int a, int b) {
  SeparatrixTracer<TMesh> t(m);
  ConnectingPath p = t.Connect(a, b, 50);
  return p ? p.first[1] : -1;
}

/// Direction of the step from a to b in the plane, as a multiple of 60 degrees (0..5).
int Sector(TMesh& m, int a, int b) {
  const P3 d = m.vert[size_t(b)].P() - m.vert[size_t(a)].P();
  const double ang = std::atan2(double(d[1]), double(d[0]));
  return int(std::lround(ang / (M_PI / 3)) + 6) % 6;
}

CompositeOptions NoRelax() {
  CompositeOptions o;
  o.relax = false;
  return o;
}
}  // namespace

// Sec. 7.1.1: "the relative position of the two vertices remains the same". For each lead
// (the v5, then the v7) and each of its neighbours: the lead lands on exactly that neighbour;
// the neighbourhood of the pair (radius separation + 3, rooted at the lead and the first edge
// of the connecting path) is, up to renaming, exactly the one before (so the partner moved
// with the lead: a translation, not a rotation, since both moved by one edge over a
// separation of 3 or more); the partner lands next to where it was; no other irregular vertex
// changes. All six lattice directions are realised, from one lead or the other.
TEST(PairMovement, NonAdjacent57PairTranslatesByTheLeadsLatticeStep) {
  for (int separation : {3, 4}) {
    SeparatedPair sp;
    sp.Build(separation);
    if (HasFatalFailure()) return;
    TMesh& m = sp.m;
    MeshEditor<TMesh> ed(m, Combinatorial());
    CompositeOperations<TMesh> co(ed, nullptr, NoRelax());
    const std::map<int, int> before = Irregular(m);
    const auto snap = test::Snapshot(m);
    const int radius = separation + 1;
    const auto form0 = CanonicalNeighbourhood(m, sp.v5, FirstOnPath(m, sp.v5, sp.v7), radius);
    std::set<int> sectors;  // lattice directions realised
    int moved = 0;
    for (int leadIsV5 : {1, 0}) {
      const int lead = leadIsV5 ? sp.v5 : sp.v7, partner = leadIsV5 ? sp.v7 : sp.v5;
      const int d = ed.Valence(lead);
      for (int k = 0; k < d; ++k) {
        const int x = co.atomic().NeighbourFrom(lead, -1, d == 7 ? k + 1 : k);  // fig. 7: a v7 lands on k + 1
        const int sector = Sector(m, lead, x);
        auto cp = ed.Mark();
        CompositeOutcome o = co.MovePair(lead, partner, k, 1);
        if (o) {
          ++moved;
          SCOPED_TRACE(testing::Message() << "separation " << separation << ", lead v" << d << ", k " << k << "\n"
                                          << o.log);
          EXPECT_EQ(o.lead, x);
          EXPECT_EQ(ed.Valence(o.lead), d);
          ASSERT_GE(o.partner, 0);
          EXPECT_EQ(ed.Valence(o.partner), 12 - d);
          const int new5 = leadIsV5 ? o.lead : o.partner, new7 = leadIsV5 ? o.partner : o.lead;
          EXPECT_EQ(CanonicalNeighbourhood(m, new5, FirstOnPath(m, new5, new7), radius), form0);
          if (ed.IsLive(partner)) EXPECT_TRUE(ed.Adjacent(partner, o.partner));
          // the irregular vertices: the pair moved, nothing else
          std::map<int, int> expect = before;
          expect.erase(lead);
          expect.erase(partner);
          expect[o.lead] = d;
          expect[o.partner] = 12 - d;
          EXPECT_EQ(Irregular(m), expect);
          EXPECT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
          sectors.insert(sector);
        }
        ed.RollbackTo(cp);
      }
    }
    EXPECT_EQ(test::Snapshot(m), snap);
    EXPECT_GE(moved, 6);
    EXPECT_EQ(sectors.size(), 6u) << "separation " << separation << ": not all six lattice directions were realised";
  }
}

// ---------------------------------------------------------------- sec. 7.1.2: 5-5 and 7-7
namespace {

/// A planar hexagonal patch (radius 14, unit edges, lattice positions) holding an adjacent
/// pair of equal valence `keep` (5 or 7) at the centre: the quadruple of a flip (fig. 8)
/// whose two vertices of the other valence are each moved `away` steps off with the atomic
/// move with pair generation (fig. 7), every generated 5-7 pair parked at least 7 edges
/// away. Built with the atomic operations only.
struct SameValencePair {
  TMesh m;
  int a = -1, b = -1;
  void Build(int keep, int away) {
    test::HexPatch(m, 14);
    MeshEditor<TMesh> ed(m, Combinatorial());
    AtomicOperations<TMesh> ops(ed);
    const int n = ed.Index(ed.Star(0).neighbors[0]);
    int o[2];
    ASSERT_TRUE(ed.Opposites(0, n, o));
    ASSERT_TRUE(ed.Flip(0, n).ok);  // 0, n -> v5; o0, o1 -> v7
    a = keep == 5 ? 0 : o[0];
    b = keep == 5 ? n : o[1];
    int mv[2] = {keep == 5 ? o[0] : 0, keep == 5 ? o[1] : n};
    std::vector<P3> parked;
    for (int s = 0; s < away; ++s)
      for (int i = 0; i < 2; ++i) {
        const P3 mid = (m.vert[size_t(a)].P() + m.vert[size_t(b)].P()) / 2;
        const P3 other = m.vert[size_t(mv[1 - i])].P();
        const int d = ed.Valence(mv[i]);
        int bestK = -1;
        float bestD = -1;
        for (int k = 0; k < d; ++k) {
          auto cp = ed.Mark();
          AtomicOutcome g = ops.MoveWithPairGeneration(mv[i], k);
          if (g) {
            const P3 q = m.vert[size_t(g.irregular[0])].P();
            const float dd = std::min((q - mid).Norm(), (q - other).Norm());
            if (dd > bestD) bestD = dd, bestK = k;
          }
          ed.RollbackTo(cp);
        }
        ASSERT_GE(bestK, 0);
        AtomicOutcome g = ops.MoveWithPairGeneration(mv[i], bestK);
        ASSERT_TRUE(g);
        mv[i] = g.irregular[0];
        int g5 = g.irregular[1], g7 = g.irregular[2];
        if (ed.Valence(g5) != 5) std::swap(g5, g7);
        std::vector<P3> away{m.vert[size_t(a)].P(), m.vert[size_t(b)].P(), m.vert[size_t(mv[0])].P(),
                             m.vert[size_t(mv[1])].P()};
        Park(ed, ops, g5, g7, away, 7);
      }
    ASSERT_EQ(ed.Valence(a), keep);
    ASSERT_EQ(ed.Valence(b), keep);
    ed.Commit();
  }
};

/// Lattice coordinates (axial) of a position of the planar patch, and whether it is one.
/// `tol` > 0: the nearest lattice point within tol (edge lengths).
bool LatticeOf(const P3& p, int& q, int& r, double tol = 1e-4) {
  const double rr = double(p[1]) / (std::sqrt(3.0) / 2), qq = double(p[0]) - 0.5 * rr;
  q = int(std::lround(qq));
  r = int(std::lround(rr));
  return (p - test::LatticePoint(q, r)).Norm() < tol;
}
}  // namespace

namespace {

/// The neighbour index k for MovePair that moves `lead` by the lattice step (sq, sr), or -1.
int KTowards(TMesh& m, CompositeOperations<TMesh>& co, int lead, int sq, int sr, double tol) {
  int lq, lr;
  if (!LatticeOf(m.vert[size_t(lead)].P(), lq, lr, tol)) return -1;
  const int d = StarOf<TMesh>(&m.vert[size_t(lead)]).Valence();
  for (int k = 0; k < d; ++k) {
    const int x = co.atomic().NeighbourFrom(lead, -1, d == 7 ? k + 1 : k);
    int xq, xr;
    if (x >= 0 && LatticeOf(m.vert[size_t(x)].P(), xq, xr, tol) && xq - lq == sq && xr - lr == sr) return k;
  }
  return -1;
}

const int kLatticeSteps[6][2] = {{1, 0}, {0, 1}, {-1, 1}, {-1, 0}, {0, -1}, {1, -1}};

/// One pair, one lead, one lattice direction s: up to `steps` MovePair steps (relaxation off),
/// each moving the lead by s. Per accepted step: whether the partner made exactly the mirrored
/// step -s, and what it made instead.
struct MirrorRun {
  int accepted = 0, mirrored = 0, offLattice = 0;
  bool firstOffLattice = false;  ///< the first step already left the partner off the lattice
  std::vector<std::string> wrong;
};
MirrorRun RunMirrored(TMesh& m, MeshEditor<TMesh>& ed, CompositeOperations<TMesh>& co, int lead, int partner,
                      int keep, int dir, int steps, double tol) {
  MirrorRun run;
  std::map<int, int> before = Irregular(m);
  const int sq = kLatticeSteps[dir][0], sr = kLatticeSteps[dir][1];
  for (int s = 0; s < steps; ++s) {
    const int k = KTowards(m, co, lead, sq, sr, tol);
    int lq, lr, pq, pr;
    if (k < 0 || !LatticeOf(m.vert[size_t(lead)].P(), lq, lr, tol) || !LatticeOf(m.vert[size_t(partner)].P(), pq, pr, tol))
      break;
    CompositeOutcome o = co.MovePair(lead, partner, k, 1);
    if (!o) break;
    ++run.accepted;
    int oq, or_, tq, tr;
    EXPECT_TRUE(LatticeOf(m.vert[size_t(o.lead)].P(), oq, or_, tol));
    EXPECT_EQ(oq - lq, sq);
    EXPECT_EQ(or_ - lr, sr);
    EXPECT_EQ(ed.Valence(o.lead), keep);
    EXPECT_EQ(ed.Valence(o.partner), keep);
    // every other irregular vertex stays where it was (the lead and the partner moved)
    std::map<int, int> expect = before;
    expect.erase(lead);
    expect.erase(partner);
    expect[o.lead] = keep;
    expect[o.partner] = keep;
    EXPECT_EQ(Irregular(m), expect);
    before = expect;
    EXPECT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
    if (!LatticeOf(m.vert[size_t(o.partner)].P(), tq, tr, tol)) {
      // a collapse survivor at the midpoint of two lattice points: one of them must be the
      // mirror point M (2 p - M then is a lattice neighbour of M)
      const P3 mp = test::LatticePoint(pq - sq, pr - sr), pp = m.vert[size_t(o.partner)].P(), other = pp * 2.f - mp;
      int nq, nr;
      const bool atMirrorEdge = LatticeOf(other, nq, nr, tol) && std::abs((other - mp).Norm() - 1.f) < 1e-4f;
      run.offLattice += atMirrorEdge;
      run.firstOffLattice = run.firstOffLattice || s == 0;
      run.wrong.push_back(testing::PrintToString(std::vector<int>{sq, sr}) + " -> partner " + std::to_string(o.partner) +
                          " off the lattice at " + std::to_string(pp[0]) + "," + std::to_string(pp[1]) +
                          (atMirrorEdge ? ", the midpoint of the mirror point and its neighbour "
                                        : ", NOT next to the mirror point ") +
                          std::to_string(mp[0]) + "," + std::to_string(mp[1]) + "\n" + o.log);
    } else if (tq - pq == -sq && tr - pr == -sr) {
      ++run.mirrored;
    } else {
      run.wrong.push_back("lead step " + testing::PrintToString(std::vector<int>{sq, sr}) + ", partner step " +
                          testing::PrintToString(std::vector<int>{tq - pq, tr - pr}));
    }
    lead = o.lead;
    partner = o.partner;
  }
  return run;
}
}  // namespace

// Sec. 7.1.2: a 5-5 pair and a 7-7 pair move symmetrically (Δd1 = Δd3, Δd2 = Δd4): when the
// lead steps by the lattice vector s onto its neighbour, the partner steps by -s (the point
// mirror through the pair's midpoint). For each pair (adjacent, at the centre of a lattice
// patch), each lead and each of the six lattice directions, up to three MovePair steps in a
// row, relaxation off (a vertex that only changes valence keeps its lattice point): the lead
// lands exactly on lead + s each time, both keep their valence, the number of irregular
// vertices is kept, the invariants hold; and the partner lands exactly on partner - s. Where
// the transport's split and the cancelling collapse re-mesh the partner's site, the survivor
// sits at the midpoint of two lattice points; the test then asserts that one of them is the
// mirror point (weaker: the survivor stands for two sites) and prints the case.
TEST(PairMovement, SameValencePairsMoveByMirroredLatticeSteps) {
  for (int keep : {5, 7}) {
    SCOPED_TRACE(testing::Message() << keep << "-" << keep << " pair");
    SameValencePair sp;
    sp.Build(keep, 3);
    if (HasFatalFailure()) return;
    TMesh& m = sp.m;
    MeshEditor<TMesh> ed(m, Combinatorial());
    CompositeOperations<TMesh> co(ed, nullptr, NoRelax());
    const auto snap = test::Snapshot(m);
    int accepted = 0, mirrored = 0, offLattice = 0, crossChecked = 0, crossSame = 0;
    std::vector<std::string> notes;
    for (int leadIsA : {1, 0})
      for (int dir = 0; dir < 6; ++dir) {
        const int lead = leadIsA ? sp.a : sp.b, partner = leadIsA ? sp.b : sp.a;
        auto cp = ed.Mark();
        MirrorRun r = RunMirrored(m, ed, co, lead, partner, keep, dir, 3, 1e-4);
        ed.RollbackTo(cp);
        accepted += r.accepted;
        mirrored += r.mirrored;
        offLattice += r.offLattice;
        for (auto& w : r.wrong) notes.push_back("lead " + std::to_string(lead) + ": " + w);
        if (r.firstOffLattice) {
          // the same move led by the other vertex (partner by -s) must give the same mesh: its
          // lead lands exactly on partner - s, so the re-meshed survivor here stands for it.
          // Compared by the canonical neighbourhood of a far, untouched vertex (radius 11).
          const int root = test::At(m, -7, 0), first = test::At(m, -7, 1);
          ASSERT_GE(root, 0);
          ASSERT_GE(first, 0);
          RunMirrored(m, ed, co, lead, partner, keep, dir, 1, 1e-4);
          const auto formA = CanonicalNeighbourhood(m, root, first, 11);
          ed.RollbackTo(cp);
          MirrorRun b = RunMirrored(m, ed, co, partner, lead, keep, (dir + 3) % 6, 1, 1e-4);
          const auto formB = CanonicalNeighbourhood(m, root, first, 11);
          ed.RollbackTo(cp);
          EXPECT_EQ(b.accepted, 1) << "the move led by the other vertex is refused";
          EXPECT_TRUE(formA == formB) << "lead " << lead << ", direction " << dir
                                      << ": led by the other vertex the mirrored move gives another mesh";
          ++crossChecked;
          crossSame += formA == formB;
        }
      }
    EXPECT_EQ(test::Snapshot(m), snap);
    std::printf("%d-%d pair: %d steps accepted, %d with the partner exactly on the mirror lattice point, %d with it "
                "at the midpoint of the mirror point and a neighbour (re-meshed; %d of %d such first steps give the same mesh "
                "as the move led by the other vertex)\n",
                keep, keep, accepted, mirrored, offLattice, crossSame, crossChecked);
    for (auto& w : notes) std::printf("  %s\n", w.c_str());
    EXPECT_GE(accepted, 6);
    EXPECT_EQ(mirrored + offLattice, accepted) << "sec. 7.1.2: a partner's step is not the mirror image of the lead's";
  }
}
