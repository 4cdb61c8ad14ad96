// filter_irregular: input diagnosis and mesh invariants.
//
// DiagnoseInput() tells whether a mesh is fit for the irregular-vertex operations and, if not,
// says what is wrong and which MeshLab filter repairs it. CheckInvariants() is the full
// consistency check the tests run after every edit (DEVELOPERS.md: manifold, FF/VF consistent,
// consistent orientation, no valence < 3, no duplicate edges, Gauss-Bonnet identity).
//
// Both only read the mesh (vcg Visited flags are not used).
#pragma once

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <vcg/complex/complex.h>

#include "result.h"
#include "topology.h"

namespace vcg_ext {
namespace irregular {

/// What DiagnoseInput found. Counts of defects; all zero for a clean manifold triangle mesh.
struct InputReport {
  int faces = 0;
  int polygonFaces = 0;         ///< triangles that MeshLab made out of polygons (faux edges)
  int degenerateFaces = 0;      ///< a vertex repeated in a face, or zero area
  int nonManifoldEdges = 0;     ///< edges shared by more than two faces
  int nonManifoldVertices = 0;  ///< vertices whose faces form more than one fan
  int unreferencedVertices = 0;
  int duplicateVertices = 0;    ///< vertices at exactly the same position as another
  int misorientedEdges = 0;     ///< interior edges whose two faces disagree on orientation
  int components = 0;
  int boundaryEdges = 0;

  /// The first blocking problem in words a user understands, naming the MeshLab filter that
  /// fixes it; Ok() if none. Boundaries and several components are allowed here (the
  /// operations that need otherwise check it themselves).
  Result Verdict() const {
    std::ostringstream o;
    if (faces == 0) return Result::Fail("The mesh has no faces: the irregular-vertex filters need a triangle mesh.");
    if (polygonFaces > 0) {
      o << "The mesh has polygonal faces (" << polygonFaces
        << " triangles belong to polygons). Triangulate it first with "
           "'Turn into a Pure-Triangular mesh'.";
      return Result::Fail(o.str());
    }
    if (nonManifoldEdges > 0) {
      o << "The mesh is not manifold: " << nonManifoldEdges
        << " edges are shared by more than two faces. Repair it with 'Repair non Manifold Edges'.";
      return Result::Fail(o.str());
    }
    if (degenerateFaces > 0) {
      o << "The mesh has " << degenerateFaces
        << " degenerate faces (repeated vertex or zero area). Remove them with "
           "'Remove Duplicate Faces' and 'Remove Zero Area Faces'.";
      return Result::Fail(o.str());
    }
    if (nonManifoldVertices > 0) {
      o << "The mesh is not manifold: " << nonManifoldVertices
        << " vertices join separate fans of faces. Repair it with 'Repair non Manifold Vertices', with a "
           "Vertex Displacement Ratio above 0 (0.05: at 0 the copies it makes stay at one position, and are "
           "refused as duplicated vertices).";
      return Result::Fail(o.str());
    }
    if (misorientedEdges > 0) {
      o << "The faces are not consistently oriented (" << misorientedEdges
        << " edges). Fix it with 'Re-Orient all faces coherentely'.";
      return Result::Fail(o.str());
    }
    if (duplicateVertices > 0) {
      o << "The mesh has " << duplicateVertices
        << " duplicated vertices (same position), so its connectivity is cut where it should not "
           "be. Merge them with 'Remove Duplicate Vertices' (unless 'Repair non Manifold Vertices' made them: "
           "merging would join its fans again; run it again with a Vertex Displacement Ratio above 0, such as "
           "0.05).";
      return Result::Fail(o.str());
    }
    if (unreferencedVertices > 0) {
      o << "The mesh has " << unreferencedVertices
        << " vertices that no face uses. Remove them with 'Remove Unreferenced Vertices'.";
      return Result::Fail(o.str());
    }
    return Result::Ok();
  }
};

/// Number of faces in the fan of c.f->V(c.z) reachable through FF (stops after bound). O(valence).
template <class FaceType>
int FanSize(Corner<FaceType> c, int bound) {
  const Corner<FaceType> start = c;
  for (int k = 0; k < bound; ++k) {  // rewind clockwise to a boundary, or all the way round
    Corner<FaceType> p = NextCornerCW(c);
    if (p.f == nullptr) break;
    c = p;
    if (c.f == start.f && c.z == start.z) break;
  }
  int n = 1;
  const Corner<FaceType> first = c;
  for (; n <= bound; ++n) {
    Corner<FaceType> nx = NextCornerCCW(c);
    if (nx.f == nullptr) break;
    c = nx;
    if (c.f == first.f && c.z == first.z) break;
  }
  return n;
}

/// Reads the mesh and counts every defect that would make valence meaningless or an edit unsafe.
/// Precondition: FF adjacency computed by vcg::tri::UpdateTopology::FaceFace (which links
/// non-manifold edges in a cycle; that is detected here). O(F log F).
template <class MeshType>
InputReport DiagnoseInput(MeshType& m) {
  typedef typename MeshType::FaceType FaceType;
  typedef typename MeshType::CoordType CoordType;
  InputReport r;
  std::vector<int> facesAt(m.vert.size(), 0);
  for (size_t i = 0; i < m.face.size(); ++i) {
    FaceType& f = m.face[i];
    if (f.IsD()) continue;
    ++r.faces;
    bool poly = false;
    for (int z = 0; z < 3; ++z) {
      if (f.IsF(z)) poly = true;
      facesAt[vcg::tri::Index(m, f.V(z))]++;
    }
    if (poly) ++r.polygonFaces;
    const bool repeated = f.V(0) == f.V(1) || f.V(1) == f.V(2) || f.V(2) == f.V(0);
    const CoordType n = (f.P(1) - f.P(0)) ^ (f.P(2) - f.P(0));
    if (repeated || n.Norm() == 0) ++r.degenerateFaces;
    for (int z = 0; z < 3; ++z) {
      FaceType* g = f.FFp(z);
      const int j = f.FFi(z);
      if (g == &f) {
        ++r.boundaryEdges;
        continue;
      }
      if (g->FFp(j) != &f || g->FFi(j) != z) {
        // vcg links the faces of a non-manifold edge in a cycle: count each edge once.
        if (&f < g) ++r.nonManifoldEdges;
        continue;
      }
      if (&f < g && !(g->V(j) == f.V((z + 1) % 3) && g->V((j + 1) % 3) == f.V(z))) ++r.misorientedEdges;
    }
  }
  // Non-manifold vertices: the fan reached from one face through FF must hold every face of v.
  // Only meaningful on manifold, consistently oriented edges (the fan walk follows the
  // orientation), so skip when those failed: their message is the one that helps.
  if (r.nonManifoldEdges == 0 && r.degenerateFaces == 0 && r.misorientedEdges == 0) {
    std::vector<char> done(m.vert.size(), 0);
    for (size_t i = 0; i < m.face.size(); ++i) {
      FaceType* f = &m.face[i];
      if (f->IsD()) continue;
      for (int z = 0; z < 3; ++z) {
        size_t vi = vcg::tri::Index(m, f->V(z));
        if (done[vi]) continue;
        done[vi] = 1;
        const int fanFaces = FanSize(Corner<FaceType>{f, z}, facesAt[vi] + 2);
        if (fanFaces != facesAt[vi]) ++r.nonManifoldVertices;
      }
    }
  }
  for (size_t i = 0; i < m.vert.size(); ++i)
    if (!m.vert[i].IsD() && facesAt[i] == 0) ++r.unreferencedVertices;
  {
    std::vector<std::tuple<double, double, double>> pts;
    pts.reserve(m.vert.size());
    for (size_t i = 0; i < m.vert.size(); ++i)
      if (!m.vert[i].IsD() && facesAt[i] > 0)
        pts.emplace_back(m.vert[i].P()[0], m.vert[i].P()[1], m.vert[i].P()[2]);
    std::sort(pts.begin(), pts.end());
    for (size_t i = 1; i < pts.size(); ++i)
      if (pts[i] == pts[i - 1]) ++r.duplicateVertices;
  }
  r.components = CountComponents(m);
  return r;
}

/// Faces whose normal turns by more than maxAngleDeg against an edge neighbour, counted per
/// edge. A fold in the surface; edits must never create one.
template <class MeshType>
int CountFoldedEdges(MeshType& m, double maxAngleDeg = 150.0) {
  const double c = std::cos(maxAngleDeg * M_PI / 180.0);
  int folds = 0;
  for (auto fi = m.face.begin(); fi != m.face.end(); ++fi) {
    if (fi->IsD()) continue;
    auto n0 = vcg::TriangleNormal(*fi);
    for (int z = 0; z < 3; ++z) {
      auto g = fi->FFp(z);
      if (g == &*fi || g < &*fi) continue;
      auto n1 = vcg::TriangleNormal(*g);
      double d = double(n0.Norm()) * double(n1.Norm());
      if (d == 0 || double(n0.dot(n1)) / d < c) ++folds;
    }
  }
  return folds;
}

/// Full consistency check of an edited mesh. O(F + V). Checks, in order:
/// live faces reference live, distinct vertices; FF symmetric and orientation consistent;
/// VF lists hold exactly the corners of each vertex; every vertex is a single manifold fan;
/// interior valence >= 3; a consistent boundary (every vertex on a boundary edge has exactly
/// two boundary edges, one leaving and one entering it, and its fan runs from one to the
/// other; valence >= 2); no duplicate edge; Gauss-Bonnet identity (eq. 2, boundary vertices
/// counted against 4).
/// Needs FF and VF adjacency.
template <class MeshType>
Result CheckInvariants(MeshType& m) {
  typedef typename MeshType::FaceType FaceType;
  typedef typename MeshType::VertexType VertexType;
  std::ostringstream o;
  std::vector<int> corners(m.vert.size(), 0);
  std::vector<int> borderOut(m.vert.size(), 0), borderIn(m.vert.size(), 0);  // boundary edges leaving / entering
  for (size_t i = 0; i < m.face.size(); ++i) {
    FaceType& f = m.face[i];
    if (f.IsD()) continue;
    for (int z = 0; z < 3; ++z) {
      if (f.V(z) == nullptr || f.V(z)->IsD()) {
        o << "face " << i << " references a deleted vertex";
        return Result::Fail(o.str());
      }
      corners[vcg::tri::Index(m, f.V(z))]++;
    }
    if (f.V(0) == f.V(1) || f.V(1) == f.V(2) || f.V(0) == f.V(2)) {
      o << "face " << i << " repeats a vertex";
      return Result::Fail(o.str());
    }
    for (int z = 0; z < 3; ++z) {
      FaceType* g = f.FFp(z);
      const int j = f.FFi(z);
      if (g == nullptr || g->IsD()) {
        o << "face " << i << " edge " << z << " is adjacent to a deleted face";
        return Result::Fail(o.str());
      }
      if (g == &f) {
        if (j != z) {
          o << "face " << i << " border edge " << z << " has FFi " << j;
          return Result::Fail(o.str());
        }
        borderOut[vcg::tri::Index(m, f.V(z))]++;
        borderIn[vcg::tri::Index(m, f.V((z + 1) % 3))]++;
        continue;
      }
      if (g->FFp(j) != &f || g->FFi(j) != z) {
        o << "FF adjacency of face " << i << " edge " << z << " is not symmetric";
        return Result::Fail(o.str());
      }
      if (!(g->V(j) == f.V((z + 1) % 3) && g->V((j + 1) % 3) == f.V(z))) {
        o << "faces " << i << " and " << vcg::tri::Index(m, g)
          << " share an edge but are not consistently oriented (or FF points to a wrong face)";
        return Result::Fail(o.str());
      }
    }
  }
  const bool hasVF = vcg::tri::HasPerVertexVFAdjacency(m) && vcg::tri::HasPerFaceVFAdjacency(m);
  for (size_t vi = 0; vi < m.vert.size(); ++vi) {
    VertexType* v = &m.vert[vi];
    if (v->IsD()) continue;
    if (corners[vi] == 0) continue;  // unreferenced vertices carry no topology
    if (hasVF) {
      int n = 0;
      for (vcg::face::VFIterator<FaceType> it(v); !it.End(); ++it) {
        if (it.F()->IsD() || it.F()->V(it.I()) != v) {
          o << "VF list of vertex " << vi << " holds a wrong corner";
          return Result::Fail(o.str());
        }
        if (++n > corners[vi]) break;
      }
      if (n != corners[vi]) {
        o << "VF list of vertex " << vi << " has " << n << " corners, faces reference it "
          << corners[vi] << " times";
        return Result::Fail(o.str());
      }
      VertexStar<MeshType> s = StarOf<MeshType>(v);
      if (!s.manifold || int(s.corners.size()) != corners[vi]) {
        o << "vertex " << vi << " is not a single manifold fan";
        return Result::Fail(o.str());
      }
      if (!s.boundary && s.Valence() < 3) {
        o << "vertex " << vi << " has valence " << s.Valence() << " (< 3)";
        return Result::Fail(o.str());
      }
      // Boundary consistency: a single fan (above) from an entering to a leaving boundary edge.
      const bool onBorder = borderOut[vi] + borderIn[vi] > 0;
      if (onBorder != s.boundary || (onBorder && (borderOut[vi] != 1 || borderIn[vi] != 1))) {
        o << "vertex " << vi << " has an inconsistent boundary (" << borderOut[vi] << " boundary edges leaving, "
          << borderIn[vi] << " entering, fan " << (s.boundary ? "open" : "closed") << ")";
        return Result::Fail(o.str());
      }
      if (s.boundary && s.Valence() < 2) {
        o << "boundary vertex " << vi << " has valence " << s.Valence() << " (< 2)";
        return Result::Fail(o.str());
      }
      std::vector<VertexType*> nb(s.neighbors.begin(), s.neighbors.end());
      std::sort(nb.begin(), nb.end());
      if (std::adjacent_find(nb.begin(), nb.end()) != nb.end()) {
        o << "vertex " << vi << " has a duplicate edge";
        return Result::Fail(o.str());
      }
    }
  }
  TopologySummary ts = Summarize(m);
  if (!ts.GaussBonnetHolds()) {
    o << "Gauss-Bonnet identity fails: sum of defects " << ts.gaussBonnetSum << " != 6 * chi = "
      << 6 * ts.eulerCharacteristic;
    return Result::Fail(o.str());
  }
  return Result::Ok();
}

}  // namespace irregular
}  // namespace vcg_ext
