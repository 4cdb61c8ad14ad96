// Unit tests of vcg_ext/irregular/attribute_transfer.h through the graph and atomic operations
// (issue 13, item 5): on a planar lattice patch whose texture coordinates, vertex quality and
// vertex texture coordinates are an affine function of position, every edited corner must
// still carry that function of its vertex's position; face colours follow the documented
// rules; rollback restores every attribute exactly; a texture seam is refused by the dry run
// and the operation alike, leaving the mesh unchanged.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <tuple>

#include <vcg_ext/irregular/atomic_ops.h>
#include <vcg_ext/irregular/mesh_checks.h>
#include <vcg_ext/irregular/relaxation.h>
#include <vcg_ext/irregular/surface_projector.h>

#include "test_mesh.h"
#include "test_util.h"

using namespace vcg_ext::irregular;
using test::TAMesh;
using test::TOMesh;

namespace {

// The parametrisation: an affine map of the plane (the patch lies in z = 0).
template <class P>
vcg::Point2f Param(const P& p) {
  return vcg::Point2f(0.13f * p[0] + 0.05f * p[1] + 0.2f, -0.04f * p[0] + 0.11f * p[1] + 0.6f);
}
template <class P>
float QualityAt(const P& p) {
  return 2.f * p[0] - p[1] + 10.f;
}

// Face colour and quality that identify a face: colour from its index, quality = index.
vcg::Color4b ColorOf(size_t i) {
  return vcg::Color4b((unsigned char)(i * 37 % 251), (unsigned char)(i * 91 % 241), (unsigned char)(i % 200), 255);
}

/// Texture coordinates (wedge and vertex) and vertex quality from the positions; face colours
/// and qualities from the face indices; vertex colour from the position (red = 10 x + 100).
template <class MeshT>
void Paint(MeshT& m, float offsetAbove = 0, float seamY = 1e9f) {
  for (size_t i = 0; i < m.face.size(); ++i) {
    auto& f = m.face[i];
    if (f.IsD()) continue;
    const float cy = (f.P(0)[1] + f.P(1)[1] + f.P(2)[1]) / 3;
    for (int z = 0; z < 3; ++z) {
      f.WT(z).P() = Param(f.P(z));
      f.WT(z).N() = 0;
      if (cy > seamY) f.WT(z).U() += offsetAbove;
    }
    f.C() = ColorOf(i);
    f.Q() = float(i);
  }
  for (auto& v : m.vert) {
    v.T().P() = Param(v.P());
    v.Q() = QualityAt(v.P());
    v.C() = vcg::Color4b((unsigned char)std::lround(10 * v.P()[0] + 100), 50, 60, 255);
  }
}

/// Every live corner's texture coordinate (and vertex texcoord) equals the parametrisation at
/// its vertex (+offsetAbove for faces above seamY); returns the number of corners checked.
template <class MeshT>
int ExpectAffine(MeshT& m, float offsetAbove = 0, float seamY = 1e9f) {
  int n = 0;
  for (auto& f : m.face) {
    if (f.IsD()) continue;
    const float cy = (f.P(0)[1] + f.P(1)[1] + f.P(2)[1]) / 3;
    for (int z = 0; z < 3; ++z, ++n) {
      vcg::Point2f want = Param(f.P(z));
      if (cy > seamY) want[0] += offsetAbove;
      EXPECT_NEAR(f.WT(z).U(), want[0], 1e-6) << "face " << vcg::tri::Index(m, f) << " corner " << z;
      EXPECT_NEAR(f.WT(z).V(), want[1], 1e-6) << "face " << vcg::tri::Index(m, f) << " corner " << z;
    }
  }
  for (auto& v : m.vert) {
    if (v.IsD()) continue;
    EXPECT_NEAR(v.T().U(), Param(v.P())[0], 1e-6);
    EXPECT_NEAR(v.T().V(), Param(v.P())[1], 1e-6);
  }
  return n;
}

/// Colours and qualities are copied, never mixed: every live element's (colour, quality) is
/// one the input had.
template <class MeshT>
std::set<std::tuple<int, int, int, float>> Palette(MeshT& m, bool faces) {
  std::set<std::tuple<int, int, int, float>> p;
  if (faces) {
    for (auto& f : m.face)
      if (!f.IsD()) p.insert({f.C()[0], f.C()[1], f.C()[2], f.Q()});
  } else {
    for (auto& v : m.vert)
      if (!v.IsD()) p.insert({v.C()[0], v.C()[1], v.C()[2], v.Q()});
  }
  return p;
}
template <class MeshT>
void ExpectCopiedValues(MeshT& m, const std::set<std::tuple<int, int, int, float>>& faces,
                        const std::set<std::tuple<int, int, int, float>>& verts) {
  for (auto& key : Palette(m, true)) EXPECT_TRUE(faces.count(key)) << "a face colour or quality was mixed";
  for (auto& key : Palette(m, false)) EXPECT_TRUE(verts.count(key)) << "a vertex colour or quality was mixed";
}

/// Everything, attributes included, by index.
template <class MeshT>
std::vector<std::vector<double>> FullSnapshot(MeshT& m) {
  std::vector<std::vector<double>> s{{double(m.fn), double(m.vn), double(m.face.size()), double(m.vert.size())}};
  auto fi = [&](const typename MeshT::FaceType* f) { return f ? double(vcg::tri::Index(m, f)) : -1.0; };
  for (auto& v : m.vert)
    s.push_back({v.P()[0], v.P()[1], v.P()[2], double(v.Flags()), fi(v.cVFp()), double(v.cVFi()), v.T().U(),
                 v.T().V(), double(v.T().N()), v.Q(), double(v.C()[0]), double(v.C()[1]), double(v.C()[2])});
  for (auto& f : m.face) {
    std::vector<double> r{double(f.Flags()), f.Q(), double(f.C()[0]), double(f.C()[1]), double(f.C()[2])};
    for (int z = 0; z < 3; ++z) {
      for (double d : {f.cV(z) ? double(vcg::tri::Index(m, f.cV(z))) : -1.0, fi(f.cFFp(z)), double(f.cFFi(z)),
                       fi(f.cVFp(z)), double(f.cVFi(z)), double(f.WT(z).U()), double(f.WT(z).V()), double(f.WT(z).N())})
        r.push_back(d);
    }
    s.push_back(r);
  }
  return s;
}

/// A textured, painted hexagonal lattice patch (planar, radius in edges; centre = vertex 0).
void TexturedPatch(TAMesh& m, int radius) {
  test::TMesh base;
  test::HexPatch(base, radius);
  test::CopyWithAttributes(base, m);
  Paint(m);
}

/// The face with corners a, b (in this order along its boundary), or null.
template <class MeshT>
typename MeshT::FaceType* FaceWith(MeshT& m, int a, int b) {
  for (auto& f : m.face)
    if (!f.IsD())
      for (int z = 0; z < 3; ++z)
        if (int(vcg::tri::Index(m, f.V(z))) == a && int(vcg::tri::Index(m, f.V((z + 1) % 3))) == b) return &f;
  return nullptr;
}

}  // namespace

TEST(Attributes, FlipCarriesTexcoordsAndTheLargerFacesColour) {
  TAMesh m;
  TexturedPatch(m, 5);
  MeshEditor<TAMesh> ed(m);
  const int x = 0, y = ed.Index(ed.Star(0).neighbors[0]);
  int o[2];
  ASSERT_TRUE(ed.Opposites(x, y, o));
  // Move o0 toward the edge so the face (x, y, o0) is the smaller one; repaint for the new
  // positions.
  m.vert[size_t(o[0])].P() = m.vert[size_t(o[0])].P() * 0.7f + (m.vert[size_t(x)].P() + m.vert[size_t(y)].P()) * 0.15f;
  Paint(m);
  auto* left = FaceWith(m, x, y);
  auto* right = FaceWith(m, y, x);
  ASSERT_TRUE(left && right);
  const vcg::Color4b larger = right->C();
  const float largerQ = right->Q();
  std::vector<vcg::Color4b> before;
  for (auto& f : m.face) before.push_back(f.C());
  const size_t li = vcg::tri::Index(m, left), ri = vcg::tri::Index(m, right);
  ASSERT_TRUE(ed.Flip(x, y).ok);
  ASSERT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
  EXPECT_GT(ExpectAffine(m), 0);
  for (size_t i = 0; i < m.face.size(); ++i) {
    if (i == li || i == ri) {
      EXPECT_EQ(m.face[i].C(), larger) << "new face " << i << " takes the larger old face's colour";
      EXPECT_EQ(m.face[i].Q(), largerQ);
    } else {
      EXPECT_EQ(m.face[i].C(), before[i]) << "face " << i << " is not part of the flip";
    }
  }
  // the new edge is (o0, o1)
  EXPECT_TRUE(ed.Adjacent(o[0], o[1]));
  EXPECT_FALSE(ed.Adjacent(x, y));
}

TEST(Attributes, CollapseInterpolatesAtTheTarget) {
  TAMesh m;
  TexturedPatch(m, 5);
  MeshEditor<TAMesh> ed(m);
  const int u = 0, v = ed.Index(ed.Star(0).neighbors[2]);
  const auto pu = m.vert[size_t(u)].P(), pv = m.vert[size_t(v)].P();
  const vcg::Color4b cu = m.vert[size_t(u)].C(), cv = m.vert[size_t(v)].C();
  ASSERT_TRUE(ed.Collapse(u, v).ok);
  ASSERT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
  // v sits at the midpoint (the first target tried) and every corner at v carries the
  // parametrisation there: the midpoint of the two texture coordinates.
  EXPECT_LT((m.vert[size_t(v)].P() - (pu + pv) / 2).Norm(), 1e-6);
  const vcg::Point2f mid = (Param(pu) + Param(pv)) / 2;
  int corners = 0;
  for (auto& f : m.face)
    if (!f.IsD())
      for (int z = 0; z < 3; ++z)
        if (int(vcg::tri::Index(m, f.V(z))) == v) {
          ++corners;
          EXPECT_NEAR(f.WT(z).U(), mid[0], 1e-6);
          EXPECT_NEAR(f.WT(z).V(), mid[1], 1e-6);
        }
  EXPECT_EQ(corners, 8);  // valence 6 + 6 - 4
  // colour and quality are copied from the end nearer the target: v's own at the midpoint
  EXPECT_EQ(m.vert[size_t(v)].C(), cv);
  EXPECT_NE(cu, cv);
  EXPECT_EQ(m.vert[size_t(v)].Q(), QualityAt(pv));
  ExpectAffine(m);
}

TEST(Attributes, SplitInterpolatesAtTheNewPositionsAndNewFacesTakeTheirNeighboursColour) {
  TAMesh m;
  TexturedPatch(m, 5);
  MeshEditor<TAMesh> ed(m);
  VertexStar<TAMesh> s = ed.Star(0);
  const int w = 0, a = ed.Index(s.neighbors[0]), b = ed.Index(s.neighbors[3]);
  const vcg::Color4b cw = m.vert[size_t(w)].C();
  const float qw = m.vert[size_t(w)].Q();
  int created = -1;
  ASSERT_TRUE(ed.Split(w, a, b, &created).ok);
  ASSERT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
  ExpectAffine(m);
  for (int q : {w, created}) {
    EXPECT_EQ(m.vert[size_t(q)].C(), cw) << "split vertices keep w's colour";
    EXPECT_EQ(m.vert[size_t(q)].Q(), qw);
  }
  // w and the new vertex moved apart (otherwise interpolation was not exercised)
  EXPECT_GT((m.vert[size_t(w)].P() - m.vert[size_t(created)].P()).Norm(), 0.1);
  auto* fb = &m.face[m.face.size() - 2];  // (w, b, w')
  auto* fa = &m.face[m.face.size() - 1];  // (w, w', a)
  ASSERT_EQ(int(vcg::tri::Index(m, fa->V(2))), a);
  ASSERT_EQ(int(vcg::tri::Index(m, fb->V(1))), b);
  EXPECT_EQ(fa->C(), fa->FFp(2)->C()) << "(w, w', a) takes the colour of the old face across (a, w)";
  EXPECT_EQ(fa->Q(), fa->FFp(2)->Q());
  EXPECT_EQ(fb->C(), fb->FFp(0)->C()) << "(w, b, w') takes the colour of the old face across (w, b)";
  EXPECT_EQ(fb->Q(), fb->FFp(0)->Q());
  EXPECT_NE(fa->C(), fb->C());
}

// The atomic operations are sequences of the graph operations: a 5-5-7-7 generation and every
// one of the six 5-7 pair moves keep the parametrisation exactly.
TEST(Attributes, AtomicPairMovesCarryTheTexture) {
  TAMesh m;
  TexturedPatch(m, 9);
  MeshEditor<TAMesh> ed(m);
  AtomicOperations<TAMesh> ops(ed);
  AtomicOutcome g = ops.GenerateQuadruple(0, 0, false);
  ASSERT_TRUE(g) << g.result.reason;
  ExpectAffine(m);
  int v5 = g.irregular[0], v7 = g.irregular[2];
  ASSERT_TRUE(ed.Adjacent(v5, v7));
  // Take the pair 3 steps away from its partner (each step the direction that moves the v5
  // furthest), so that all six moves have regular neighbours; the texture holds at each step.
  const auto other = m.vert[size_t(g.irregular[1])].P();
  for (int step = 0; step < 3; ++step) {
    int best = -1;
    float bestDist = -1;
    for (int dir = 0; dir < 6; ++dir) {
      auto cp = ed.Mark();
      AtomicOutcome o = ops.MovePair57(v5, v7, dir);
      if (o && (m.vert[size_t(o.irregular[0])].P() - other).Norm() > bestDist)
        bestDist = (m.vert[size_t(o.irregular[0])].P() - other).Norm(), best = dir;
      ed.RollbackTo(cp);
    }
    ASSERT_GE(best, 0);
    AtomicOutcome o = ops.MovePair57(v5, v7, best);
    ASSERT_TRUE(o);
    ExpectAffine(m);
    v5 = o.irregular[0];
    v7 = o.irregular[1];
  }
  ed.Commit();
  const auto snap = FullSnapshot(m);
  const auto facePalette = Palette(m, true), vertPalette = Palette(m, false);
  int applied = 0;
  for (int dir = 0; dir < 6; ++dir) {
    auto cp = ed.Mark();
    AtomicOutcome o = ops.MovePair57(v5, v7, dir);
    if (!o) {
      ADD_FAILURE() << "direction " << dir << ": " << o.result.reason;
      continue;
    }
    ++applied;
    ASSERT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
    ExpectAffine(m);
    ExpectCopiedValues(m, facePalette, vertPalette);
    // a second move of the moved pair, then back to the start
    AtomicOutcome o2 = ops.MovePair57(o.irregular[0], o.irregular[1], dir);
    if (o2) ExpectAffine(m);
    ed.RollbackTo(cp);
    EXPECT_EQ(FullSnapshot(m), snap) << "direction " << dir;
  }
  EXPECT_EQ(applied, 6);
}

TEST(Attributes, RollbackRestoresEveryAttributeExactly) {
  TAMesh m;
  TexturedPatch(m, 8);
  const auto snap = FullSnapshot(m);
  const auto facePalette = Palette(m, true), vertPalette = Palette(m, false);
  MeshEditor<TAMesh> ed(m);
  auto cp = ed.Mark();
  std::mt19937 rng(11);
  int applied = 0, refused = 0;
  for (int it = 0; it < 400; ++it) {
    int v = int(rng() % m.vert.size());
    if (!ed.IsLive(v)) continue;
    VertexStar<TAMesh> s = ed.Star(v);
    const int k = int(rng() % s.neighbors.size());
    const int y = ed.Index(s.neighbors[size_t(k)]);
    auto before = FullSnapshot(m);
    Result r = (it % 3 == 0) ? ed.Flip(v, y)
               : (it % 3 == 1)
                   ? ed.Collapse(v, y)
                   : ed.Split(v, y, ed.Index(s.neighbors[size_t((k + 2) % s.neighbors.size())]));
    if (r) {
      ++applied;
    } else {
      ++refused;
      EXPECT_EQ(FullSnapshot(m), before) << "a refused operation changed the mesh: " << r.reason;
    }
  }
  EXPECT_GT(applied, 50);
  EXPECT_GT(refused, 10);
  ASSERT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
  ExpectAffine(m);
  ExpectCopiedValues(m, facePalette, vertPalette);
  ed.RollbackTo(cp);
  EXPECT_EQ(FullSnapshot(m), snap);
}

// A seam along the lattice line y = 0: faces above it have their u shifted by 0.5.
TEST(Attributes, SeamEditsAreRefusedAndLeaveTheMeshUnchanged) {
  TAMesh m;
  TexturedPatch(m, 6);
  Paint(m, 0.5f, 0.f);
  MeshEditor<TAMesh> ed(m);
  const auto snap = FullSnapshot(m);
  // vertex 0 (origin) and its neighbour at (1, 0) lie on the seam; (0,1) lies above it
  int right = -1, up = -1;
  for (auto* n : ed.Star(0).neighbors) {
    if (std::fabs(n->P()[1]) < 1e-6 && n->P()[0] > 0) right = ed.Index(n);
    if (n->P()[1] > 0.5f && n->P()[0] > 0) up = ed.Index(n);
  }
  ASSERT_GE(right, 0);
  ASSERT_GE(up, 0);
  Result can = ed.CanFlip(0, right);
  EXPECT_FALSE(can.ok);
  EXPECT_NE(can.reason.find("texture seam"), std::string::npos) << can.reason;
  Result r = ed.Flip(0, right);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.reason, can.reason) << "the dry run and the flip agree";
  EXPECT_EQ(FullSnapshot(m), snap);
  // collapses and splits at a seam vertex
  Result c = ed.Collapse(up, 0);
  EXPECT_FALSE(c.ok);
  EXPECT_NE(c.reason.find("texture seam"), std::string::npos) << c.reason;
  EXPECT_EQ(c.reason, ed.CanCollapse(up, 0).reason);
  VertexStar<TAMesh> s = ed.Star(0);
  Result sp = ed.Split(0, ed.Index(s.neighbors[0]), ed.Index(s.neighbors[3]));
  EXPECT_FALSE(sp.ok);
  EXPECT_NE(sp.reason.find("texture seam"), std::string::npos) << sp.reason;
  EXPECT_EQ(FullSnapshot(m), snap);
  // Away from the seam everything works and the shifted side keeps its shift.
  int far = -1;  // the lattice vertex (0.5, 3 sqrt(3) / 2), three rows above the seam
  for (size_t i = 0; i < m.vert.size(); ++i)
    if (std::fabs(m.vert[i].P()[0] - 0.5f) < 1e-4 && std::fabs(m.vert[i].P()[1] - 1.5f * std::sqrt(3.f)) < 1e-4)
      far = int(i);
  ASSERT_GE(far, 0);
  const int fy = ed.Index(ed.Star(far).neighbors[0]);
  ASSERT_TRUE(ed.Flip(far, fy).ok);
  ASSERT_TRUE(ed.Collapse(ed.Index(ed.Star(far).neighbors[1]), far).ok);
  ExpectAffine(m, 0.5f, 0.f);
}

TEST(Attributes, DifferentTexturesAreRefusedWithTheReason) {
  TAMesh m;
  TexturedPatch(m, 5);
  for (auto& f : m.face)
    if ((f.P(0)[1] + f.P(1)[1] + f.P(2)[1]) / 3 > 0)
      for (int z = 0; z < 3; ++z) f.WT(z).N() = 1;
  MeshEditor<TAMesh> ed(m);
  const auto snap = FullSnapshot(m);
  int right = -1;
  for (auto* n : ed.Star(0).neighbors)
    if (std::fabs(n->P()[1]) < 1e-6 && n->P()[0] > 0) right = ed.Index(n);
  Result r = ed.Flip(0, right);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.reason.find("different textures"), std::string::npos) << r.reason;
  EXPECT_EQ(FullSnapshot(m), snap);
}

// Dry runs agree with the operations on random requests on a patch with a seam: a request the
// dry run refuses is refused with the same words; one it accepts fails only on geometry.
TEST(Attributes, DryRunsAgreeOnASeamPatch) {
  TAMesh m;
  TexturedPatch(m, 7);
  Paint(m, 0.5f, 0.f);
  MeshEditor<TAMesh> ed(m);
  std::mt19937 rng(5);
  int seamRefusals = 0, applied = 0;
  for (int it = 0; it < 600; ++it) {
    int v = int(rng() % m.vert.size());
    if (!ed.IsLive(v)) continue;
    VertexStar<TAMesh> s = ed.Star(v);
    const int k = int(rng() % s.neighbors.size());
    const int y = ed.Index(s.neighbors[size_t(k)]);
    const int b = ed.Index(s.neighbors[size_t((k + 3) % s.neighbors.size())]);
    Result can = it % 3 == 0 ? ed.CanFlip(v, y) : it % 3 == 1 ? ed.CanCollapse(v, y) : ed.CanSplit(v, y, b);
    auto before = FullSnapshot(m);
    Result r = it % 3 == 0 ? ed.Flip(v, y) : it % 3 == 1 ? ed.Collapse(v, y) : ed.Split(v, y, b);
    if (!can.ok) {
      EXPECT_FALSE(r.ok);
      EXPECT_NE(r.reason.find(can.reason), std::string::npos) << r.reason << " / " << can.reason;
      EXPECT_EQ(FullSnapshot(m), before);
      seamRefusals += can.reason.find("texture seam") != std::string::npos;
    } else if (!r.ok) {
      EXPECT_TRUE(r.reason.find("fold") != std::string::npos || r.reason.find("degenerate") != std::string::npos)
          << r.reason;
    } else {
      ++applied;
    }
  }
  EXPECT_GT(seamRefusals, 5);
  EXPECT_GT(applied, 50);
  ASSERT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
  ExpectAffine(m, 0.5f, 0.f);
}

// MeshLab's optional components: disabled, nothing is read or written (vcglib would assert);
// enabled, the values are carried as with static components.
TEST(Attributes, OptionalComponentsLikeCMeshO) {
  for (bool enabled : {false, true}) {
    TOMesh m;
    m.vert.EnableVFAdjacency();
    m.vert.EnableMark();
    m.face.EnableFFAdjacency();
    m.face.EnableVFAdjacency();
    m.face.EnableMark();
    if (enabled) {
      m.face.EnableWedgeTexCoord();
      m.face.EnableColor();
      m.face.EnableQuality();
      m.vert.EnableTexCoord();
    }
    test::TMesh base;
    test::HexPatch(base, 6);
    test::CopyWithAttributes(base, m);
    if (enabled) Paint(m);
    MeshEditor<TOMesh> ed(m);
    auto cp = ed.Mark();
    VertexStar<TOMesh> s = ed.Star(0);
    ASSERT_TRUE(ed.Flip(0, ed.Index(s.neighbors[0])).ok);
    ASSERT_TRUE(ed.Collapse(ed.Index(ed.Star(0).neighbors[1]), 0).ok);
    s = ed.Star(0);
    ASSERT_TRUE(ed.Split(0, ed.Index(s.neighbors[0]), ed.Index(s.neighbors[3])).ok);
    ASSERT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
    if (enabled) {
      ExpectAffine(m);
      ed.RollbackTo(cp);
      ExpectAffine(m);
    }
  }
}

// Custom attributes (unknown type) are copied: the split's new vertex takes w's value, each
// new face its neighbour's; a flip and a collapse keep the survivors' own values.
TEST(Attributes, CustomAttributesAreCopiedBySplits) {
  TAMesh m;
  TexturedPatch(m, 5);
  auto vh = vcg::tri::Allocator<TAMesh>::AddPerVertexAttribute<int>(m, std::string("label"));
  auto fh = vcg::tri::Allocator<TAMesh>::AddPerFaceAttribute<int>(m, std::string("region"));
  for (size_t i = 0; i < m.vert.size(); ++i) vh[i] = int(1000 + i);
  for (size_t i = 0; i < m.face.size(); ++i) fh[i] = int(5000 + i);
  MeshEditor<TAMesh> ed(m);
  VertexStar<TAMesh> s = ed.Star(0);
  int created = -1;
  ASSERT_TRUE(ed.Split(0, ed.Index(s.neighbors[1]), ed.Index(s.neighbors[4]), &created).ok);
  auto vh2 = vcg::tri::Allocator<TAMesh>::GetPerVertexAttribute<int>(m, std::string("label"));
  auto fh2 = vcg::tri::Allocator<TAMesh>::GetPerFaceAttribute<int>(m, std::string("region"));
  EXPECT_EQ(vh2[size_t(created)], 1000);
  auto* fb = &m.face[m.face.size() - 2];
  auto* fa = &m.face[m.face.size() - 1];
  EXPECT_EQ(fh2[fa], fh2[fa->FFp(2)]);
  EXPECT_EQ(fh2[fb], fh2[fb->FFp(0)]);
  EXPECT_NE(fh2[fa], fh2[fb]);
  ExpectAffine(m);
  // vcg's mesh destructor does not free named attributes (LeakSanitizer)
  vcg::tri::Allocator<TAMesh>::DeletePerVertexAttribute(m, std::string("label"));
  vcg::tri::Allocator<TAMesh>::DeletePerFaceAttribute(m, std::string("region"));
}

// Relaxation moves vertices without changing the connectivity: re-sampled, the texture stays
// on the surface (every corner still the parametrisation of its new position); without the
// re-sampling it would slide with the vertices.
TEST(Attributes, ResamplingAfterRelaxationKeepsTheTextureOnTheSurface) {
  TAMesh m;
  test::TMesh base;
  test::HexPatch(base, 6);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> jitter(-0.2f, 0.2f);
  for (auto& v : base.vert)
    if (!vcg_ext::irregular::StarOf<test::TMesh>(&v).boundary) v.P() += vcg::Point3f(jitter(rng), jitter(rng), 0);
  test::CopyWithAttributes(base, m);
  Paint(m);
  std::vector<int> region;
  for (size_t i = 0; i < m.vert.size(); ++i)
    if (m.vert[i].P().Norm() < 3.5f) region.push_back(int(i));
  SurfaceProjector projector(m);
  RelaxOptions ro;
  ro.iterations = 5;
  AttributeResampler<TAMesh> keep(m, region);
  RelaxReport rep = LocalRelax(m, region, &projector, ro);
  ASSERT_GT(rep.moved, 10);
  EXPECT_GT(keep.Resample(), 10);
  ExpectAffine(m);
  // the control: the same relaxation without re-sampling leaves the texture behind
  TAMesh m2;
  test::CopyWithAttributes(base, m2);
  Paint(m2);
  SurfaceProjector projector2(m2);
  LocalRelax(m2, region, &projector2, ro);
  double worst = 0;
  for (auto& f : m2.face)
    for (int z = 0; z < 3; ++z) worst = std::max(worst, double((f.WT(z).P() - Param(f.P(z))).Norm()));
  EXPECT_GT(worst, 1e-3);
}

// A flip that is fine in space but would turn a texture triangle over is refused (a geometric
// check, like the fold check in space: the dry run, topology only, accepts it), unchanged mesh.
TEST(Attributes, TextureFoldIsRefusedAndRolledBack) {
  TAMesh m;
  TexturedPatch(m, 5);
  MeshEditor<TAMesh> ed(m);
  const int x = 0, y = ed.Index(ed.Star(0).neighbors[0]);
  int o[2];
  ASSERT_TRUE(ed.Opposites(x, y, o));
  // x's texture coordinate (at all its corners) moves past the diagonal (o0, o1) toward y:
  // the old faces keep their orientation, the new face (x, o1, o0) would turn over.
  auto at = [&](int i) { return Param(m.vert[size_t(i)].P()); };
  const vcg::Point2f mid = (at(o[0]) + at(o[1])) / 2, moved = mid + (at(y) - mid) * 0.3f;
  for (auto& f : m.face)
    for (int z = 0; z < 3; ++z)
      if (int(vcg::tri::Index(m, f.V(z))) == x) f.WT(z).P() = moved;
  EXPECT_TRUE(ed.CanFlip(x, y).ok);
  const auto snap = FullSnapshot(m);
  Result r = ed.Flip(x, y);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.reason.find("fold the texture"), std::string::npos) << r.reason;
  EXPECT_EQ(FullSnapshot(m), snap);
  // with the fold checks off, the same flip goes through
  ed.geometry().checkFolds = false;
  EXPECT_TRUE(ed.Flip(x, y).ok);
}
