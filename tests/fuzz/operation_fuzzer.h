// Random sequences of every editing operation of vcg_ext/irregular (graph, atomic, composite,
// relaxation) with random parameters, checking after each one what the project promises
// (DEVELOPERS.md): an applied operation leaves a consistent 2-manifold (CheckInvariants: FF/VF
// adjacency, orientation, manifold fans, valence >= 3, no duplicate edge, Gauss-Bonnet) whose
// locally maintained FF adjacency equals a full rebuild; a refused one leaves the mesh
// bit-identical (positions, flags, FF, VF) and gives a reason.
//
// The choices come from a ChoiceSource: a seeded std::mt19937 (fuzz_operations, the randomized
// run of the test command) or the bytes of a libFuzzer input (LLVMFuzzerTestOneInput), so one
// driver serves both.
#pragma once

#include <cstdint>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <vector>

#include <vcg_ext/irregular/composite_ops.h>
#include <vcg_ext/irregular/mesh_checks.h>
#include <vcg_ext/irregular/relaxation.h>

#include "../unit/test_mesh.h"
#include "../unit/test_util.h"

namespace fuzz {

using test::TMesh;
namespace irr = vcg_ext::irregular;

/// Where the random choices come from.
class ChoiceSource {
 public:
  virtual ~ChoiceSource() = default;
  /// A number in [0, n); n > 0.
  virtual uint32_t Below(uint32_t n) = 0;
  /// False once the source is used up (libFuzzer input consumed).
  virtual bool More() const { return true; }
};

class RandomChoices : public ChoiceSource {
 public:
  explicit RandomChoices(uint32_t seed) : rng_(seed) {}
  uint32_t Below(uint32_t n) override { return std::uniform_int_distribution<uint32_t>(0, n - 1)(rng_); }

 private:
  std::mt19937 rng_;
};

class ByteChoices : public ChoiceSource {
 public:
  ByteChoices(const uint8_t* data, size_t size) : data_(data), size_(size) {}
  uint32_t Below(uint32_t n) override {
    uint32_t x = 0;
    for (int i = 0; i < 3 && pos_ < size_; ++i) x = (x << 8) | data_[pos_++];
    return x % n;
  }
  bool More() const override { return pos_ < size_; }

 private:
  const uint8_t* data_;
  size_t size_, pos_ = 0;
};

/// The operations the fuzzer draws from.
enum class Op {
  Flip, Collapse, Split,                                                     // sec. 6.1
  MovePair57, MoveWithPairGeneration, MoveWithPairRemoval, GenerateQuadrupleAtomic, RemoveQuadruple,  // 6.2
  ReduceTo57, Aggregate,                                                     // 6.3
  MovePair, CancelTriple, CancelQuadruple, GenerateTriple, GenerateQuadruple,  // 7
  Relax,                                                                     // 8
  Count
};

inline const char* OpName(Op op) {
  static const char* names[] = {"flip", "collapse", "split", "5-7 pair move", "move with pair generation",
                                "move with pair removal", "quadruple generation (atomic)", "quadruple removal",
                                "reduce to 5/7", "aggregate", "move pair", "cancel triple", "cancel quadruple",
                                "generate triple", "generate quadruple", "relax"};
  return names[int(op)];
}

struct FuzzStats {
  std::map<Op, int> applied, refused;
  int steps = 0;
  std::string failure;  ///< empty while every check held
  bool ok() const { return failure.empty(); }
};

/// Drives random operations on one mesh. The mesh must be a valid manifold triangle mesh with
/// FF and VF adjacency (test::UpdateTopology).
class OperationFuzzer {
 public:
  OperationFuzzer(TMesh& m, ChoiceSource& choices)
      : m_(m), c_(choices), original_(m), ed_(m), comp_(ed_, &original_, FastComposite()), ops_(comp_.atomic()) {}

  /// Runs up to `steps` operations (fewer if the source runs out or a check fails).
  FuzzStats Run(int steps) {
    FuzzStats st;
    for (int i = 0; i < steps && c_.More() && st.ok(); ++i) Step(st);
    return st;
  }

 private:
  static irr::CompositeOptions FastComposite() {
    irr::CompositeOptions o;
    o.relaxIterations = 1;
    o.maxTransportSteps = 40;
    return o;
  }

  /// A live vertex: half the time an irregular one, so the semantic operations find work.
  int PickVertex() {
    const uint32_t n = uint32_t(m_.vert.size());
    if (c_.Below(2) == 0) {
      std::vector<int> irregular;
      for (uint32_t i = 0, start = c_.Below(n); i < n && irregular.size() < 8; ++i) {
        const int v = int((start + i) % n);
        if (ed_.IsLive(v) && !ed_.IsBoundary(v) && ed_.Valence(v) != 6) irregular.push_back(v);
      }
      if (!irregular.empty()) return irregular[c_.Below(uint32_t(irregular.size()))];
    }
    for (int tries = 0; tries < 64; ++tries) {
      const int v = int(c_.Below(n));
      if (ed_.IsLive(v)) return v;
    }
    for (uint32_t i = 0; i < n; ++i)
      if (ed_.IsLive(int(i))) return int(i);
    return -1;
  }

  int Neighbour(int v) {
    auto star = ed_.Star(v);
    if (star.neighbors.empty()) return -1;
    return ed_.Index(star.neighbors[c_.Below(uint32_t(star.neighbors.size()))]);
  }

  /// Mostly an irregular neighbour of v (what the semantic operations act on), else any.
  int IrregularNeighbour(int v) {
    if (c_.Below(4) != 0) {
      std::vector<int> irregular;
      for (auto* nb : ed_.Star(v).neighbors) {
        const int w = ed_.Index(nb);
        if (!ed_.IsBoundary(w) && ed_.Valence(w) != 6) irregular.push_back(w);
      }
      if (!irregular.empty()) return irregular[c_.Below(uint32_t(irregular.size()))];
    }
    return Neighbour(v);
  }

  /// v and k - 1 more vertices near it (each a neighbour of one already taken; may repeat).
  std::vector<int> Group(int v, int k) {
    std::vector<int> g{v};
    while (int(g.size()) < k) {
      const int w = IrregularNeighbour(g[c_.Below(uint32_t(g.size()))]);
      if (w < 0) break;
      if (c_.Below(4) != 0 && std::find(g.begin(), g.end(), w) != g.end()) continue;
      g.push_back(w);
    }
    return g;
  }

  /// The nearest irregular vertex other than v within a few rings (else a random vertex).
  int Partner(int v) {
    for (int x : irr::KRing(m_, {v}, 1 + int(c_.Below(4))))
      if (x != v && ed_.IsLive(x) && !ed_.IsBoundary(x) && ed_.Valence(x) != 6 && c_.Below(3) == 0) return x;
    return PickVertex();
  }

  struct Outcome {
    bool ok = false;
    std::string reason;
  };
  template <class O>
  Outcome From(const O& o) {
    if (o) recent_ = o.irregular;
    return {bool(o), o.result.reason};
  }

  /// Half the time the irregular vertices the last applied operation left (so inverses such
  /// as aggregation after a type split, or removal after a generation, get exercised), else
  /// a group grown around v.
  std::vector<int> GroupOrRecent(int v, int k) {
    if (c_.Below(2) == 0 && !recent_.empty()) {
      std::vector<int> g;
      for (int x : recent_)
        if (ed_.IsLive(x) && int(g.size()) < k) g.push_back(x);
      if (!g.empty()) return g;
    }
    return Group(v, k);
  }

  Outcome Apply(Op op) {
    const int v = PickVertex();
    if (v < 0) return {false, "no live vertex"};
    const int dir = int(c_.Below(8)) - 1;  // includes out-of-range directions: must be refused
    switch (op) {
      case Op::Flip: {
        irr::Result r = ed_.Flip(v, Neighbour(v));
        return {r.ok, r.reason};
      }
      case Op::Collapse: {
        irr::Result r = ed_.Collapse(v, Neighbour(v));
        return {r.ok, r.reason};
      }
      case Op::Split: {
        irr::Result r = ed_.Split(v, Neighbour(v), Neighbour(v));
        return {r.ok, r.reason};
      }
      case Op::MovePair57: return From(ops_.MovePair57(v, IrregularNeighbour(v), dir));
      case Op::MoveWithPairGeneration: return From(ops_.MoveWithPairGeneration(v, dir));
      case Op::MoveWithPairRemoval: return From(ops_.MoveWithPairRemoval(GroupOrRecent(v, 3)));
      case Op::GenerateQuadrupleAtomic: return From(ops_.GenerateQuadruple(v, dir, c_.Below(2) == 1));
      case Op::RemoveQuadruple: return From(ops_.RemoveQuadruple(GroupOrRecent(v, 4)));
      case Op::ReduceTo57: return From(comp_.ReduceTo57(v));
      case Op::Aggregate: return From(comp_.Aggregate(GroupOrRecent(v, 2 + int(c_.Below(2)))));
      case Op::MovePair: return From(comp_.MovePair(v, Partner(v), dir, 1 + int(c_.Below(4))));
      case Op::CancelTriple: {
        if (c_.Below(2) == 0 && recent_.size() == 3) return From(comp_.CancelTriple(GroupOrRecent(v, 3)));
        const int p = Partner(v);
        return From(comp_.CancelTriple({v, p, Partner(p)}));
      }
      case Op::CancelQuadruple: return From(comp_.CancelQuadruple(GroupOrRecent(v, 4)));
      case Op::GenerateTriple: return From(comp_.GenerateTriple(v, dir, int(c_.Below(4))));
      case Op::GenerateQuadruple: return From(comp_.GenerateQuadruple(v, dir, int(c_.Below(4))));
      case Op::Relax: {
        // relaxation never changes connectivity; the invariants must hold after it too
        irr::RelaxOptions ro;
        ro.iterations = 1 + int(c_.Below(3));
        ro.mode = c_.Below(4) == 0 ? irr::RelaxMode::Global : irr::RelaxMode::Local;
        irr::Relax(m_, irr::KRing(m_, {v}, 1 + int(c_.Below(3))), &original_, ro);
        return {true, ""};
      }
      case Op::Count: break;
    }
    return {false, "unknown operation"};
  }

  static std::string FirstDifference(const test::MeshSnapshot& a, const test::MeshSnapshot& b) {
    if (a.verts.size() != b.verts.size() || a.faces.size() != b.faces.size())
      return "element counts " + std::to_string(a.verts.size()) + "/" + std::to_string(a.faces.size()) + " -> " +
             std::to_string(b.verts.size()) + "/" + std::to_string(b.faces.size());
    for (size_t i = 0; i < a.verts.size(); ++i)
      if (a.verts[i] != b.verts[i]) {
        const auto &x = a.verts[i], &y = b.verts[i];
        char buf[200];
        std::snprintf(buf, sizeof buf, "vertex %zu: pos %s, flags %d->%d, VF (%ld,%d)->(%ld,%d)", i,
                      std::get<0>(x) == std::get<0>(y) && std::get<1>(x) == std::get<1>(y) &&
                              std::get<2>(x) == std::get<2>(y) ? "same" : "moved",
                      std::get<3>(x), std::get<3>(y), std::get<4>(x), std::get<5>(x), std::get<4>(y), std::get<5>(y));
        return buf;
      }
    for (size_t i = 0; i < a.faces.size(); ++i)
      if (a.faces[i] != b.faces[i]) {
        std::string d = "face " + std::to_string(i) + ":";
        for (size_t k = 0; k < a.faces[i].size(); ++k)
          d += " " + std::to_string(a.faces[i][k]) + (a.faces[i][k] == b.faces[i][k] ? "" : "->" + std::to_string(b.faces[i][k]));
        return d + " (flags, then per corner: V, FFp, FFi, VFp, VFi)";
      }
    return "counts (fn/vn)";
  }

  void Step(FuzzStats& st) {
    // Raw graph operations scatter irregular vertices everywhere, after which few semantic
    // operations apply: draw them a tenth as often as the others.
    Op op = Op(c_.Below(uint32_t(Op::Count)));
    if (op <= Op::Split && c_.Below(10) != 0) op = Op(int(Op::Split) + 1 + int(c_.Below(uint32_t(Op::Count) - 3)));
    const test::MeshSnapshot before = test::Snapshot(m_);
    const auto cp = ed_.Mark();
    Outcome o = Apply(op);
    ++st.steps;
    char where[96];
    std::snprintf(where, sizeof where, "step %d (%s): ", st.steps, OpName(op));
    if (!o.ok) {
      ++st.refused[op];
      if (o.reason.empty()) st.failure = std::string(where) + "refused without a reason";
      else if (!(test::Snapshot(m_) == before))
        st.failure = std::string(where) + "refused (" + o.reason + ") but the mesh changed: " +
                     FirstDifference(before, test::Snapshot(m_));
      ed_.RollbackTo(cp);  // nothing to undo if the refusal was clean; keeps the journal short
      return;
    }
    ++st.applied[op];
    ed_.Commit();
    irr::Result inv = irr::CheckInvariants(m_);
    if (!inv.ok) st.failure = std::string(where) + "invariant broken: " + inv.reason;
    else if (!test::AdjacencyEqualsRebuild(m_)) st.failure = std::string(where) + "FF adjacency differs from a rebuild";
  }

  TMesh& m_;
  ChoiceSource& c_;
  irr::SurfaceProjector original_;
  irr::MeshEditor<TMesh> ed_;
  irr::CompositeOperations<TMesh> comp_;
  irr::AtomicOperations<TMesh>& ops_;
  std::vector<int> recent_;  ///< irregular vertices left by the last applied semantic operation
};

}  // namespace fuzz
