// tests/cpd/convolution_test.cpp — mink/cpd/convolution.hpp: the compatibility predicates
// against independent definitions, in exact rationals.
//   - Convex shapes (every edge convex or flat): v is FV-compatible with face f iff v
//     minimises n_f · x over all of B (a brute-force scan in CGAL::Gmpq); the EE test
//     agrees with the Gauss-map arc test of gauss_map/arc_intersection.hpp (MDD's) on the
//     exact normals wherever that one is not Degenerate.
//   - Non-convex shapes: compatibility is local — FV(f, v) iff n_f · (w − v) >= 0 for every
//     neighbour w, scanned in Gmpq — and no reflex edge is ever EE-compatible.
//   - The facets' polygons face along their outward normals (n_f for FV, −n_g for VF,
//     ±(d_A × d_B) as the orientation says for EE), checked in Gmpq.
#include "mink/cpd/convolution.hpp"

#include <gtest/gtest.h>

#include <CGAL/Gmpq.h>

#include <Eigen/Geometry>

#include <random>
#include <string>
#include <vector>

#include "mink/gauss_map/arc_intersection.hpp"
#include "mink/polyhedron/convex_polyhedron.hpp"
#include "support/mesh_shapes.hpp"

namespace {

using Q = CGAL::Gmpq;
using Vq = mink::Vec3<Q>;
using V = Eigen::Vector3d;

/// A convex hull of random integer points as a closed triangle mesh (faces fanned).
mink_test::MeshShape hullShape(std::mt19937& rng, int n) {
  std::uniform_int_distribution<int> U(-6, 6);
  std::vector<mink::Vec3<double>> pts;
  for (int i = 0; i < n; ++i) pts.emplace_back(U(rng), U(rng), U(rng));
  const auto H = mink::ConvexPolyhedron<double>::fromPoints(pts);
  mink_test::MeshShape s;
  s.name = "hull";
  for (int v = 0; v < H.numVertices(); ++v) s.vertices.push_back(H.vertex(v));
  for (int f = 0; f < H.numFaces(); ++f) {
    const auto fv = H.faceVertices(f);
    for (int k = 1; k + 1 < fv.size(); ++k) s.triangles.push_back({fv[0], fv[k], fv[k + 1]});
  }
  return s;
}

mink::Mat3<Q> quarterTurn() {
  mink::Mat3<Q> R = mink::Mat3<Q>::Zero();
  R(0, 1) = Q(-1);
  R(1, 0) = Q(1);
  R(2, 2) = Q(1);
  return R;
}

TEST(Convolution, ConvexShapesMatchSupportAndArcs) {
  std::mt19937 rng(501);
  int fv = 0, ee = 0;
  for (int trial = 0; trial < 12; ++trial) {
    const auto sa = hullShape(rng, 14), sb = hullShape(rng, 12);
    const auto A = mink::TriangleMesh<Q>::fromMesh(sa.verticesAs<Q>(), sa.triangles);
    const auto B = mink::TriangleMesh<Q>::fromMesh(sb.verticesAs<Q>(), sb.triangles);
    mink::ConvolutionFrame<Q> frame(A, B);
    frame.place(quarterTurn(), Vq(Q(1, 3), Q(-2), Q(1, 2)));
    for (int f = 0; f < A.numTriangles(); ++f) {
      const Vq n = A.triangleNormal(f);
      Q best = n.dot(frame.b(0));
      for (int v = 1; v < B.numVertices(); ++v) best = std::min(best, Q(n.dot(frame.b(v))));
      for (int v = 0; v < B.numVertices(); ++v) {
        EXPECT_EQ(frame.compatibleFV(f, v), n.dot(frame.b(v)) == best) << "trial " << trial << " f " << f << " v " << v;
        fv += frame.compatibleFV(f, v);
      }
    }
    for (int e = 0; e < A.numEdges(); ++e) {
      if (A.edgeKind(e) != mink::EdgeKind::Convex) continue;
      const auto ta = A.edgeTriangles(e);
      for (int ep = 0; ep < B.numEdges(); ++ep) {
        if (B.edgeKind(ep) != mink::EdgeKind::Convex) continue;
        const auto tb = B.edgeTriangles(ep);
        const Vq m1 = frame.R() * B.triangleNormal(tb.first), m2 = frame.R() * B.triangleNormal(tb.second);
        // Arcs of G(A) and G(−B): the second negated.
        const auto c = mink::classifyArcs(A.triangleNormal(ta.first), A.triangleNormal(ta.second), Vq(-m1), Vq(-m2));
        if (c == mink::ArcIntersection::Degenerate) continue;
        const int o = frame.compatibleEE(e, ep);
        EXPECT_EQ(o != 0, c == mink::ArcIntersection::Proper) << "trial " << trial << " e " << e << " e' " << ep;
        ee += o != 0;
      }
    }
  }
  EXPECT_GT(fv, 0);
  EXPECT_GT(ee, 0);
}

TEST(Convolution, NonConvexCompatibilityIsLocalAndSkipsReflexEdges) {
  const std::vector<mink_test::MeshShape> shapes = {mink_test::lBlock(), mink_test::uBlock(), mink_test::cubeWithHole(),
                                                    mink_test::starPrism()};
  for (const auto& sa : shapes)
    for (const auto& sb : shapes) {
      SCOPED_TRACE(sa.name + " / " + sb.name);
      const auto A = mink::TriangleMesh<Q>::fromMesh(sa.verticesAs<Q>(), sa.triangles);
      const auto B = mink::TriangleMesh<Q>::fromMesh(sb.verticesAs<Q>(), sb.triangles);
      mink::ConvolutionFrame<Q> frame(A, B);
      frame.place(quarterTurn(), Vq(Q(1, 4), Q(3), Q(-1, 2)));
      for (int f = 0; f < A.numTriangles(); ++f)
        for (int v = 0; v < B.numVertices(); ++v) {
          bool local = true;
          for (int w : B.vertexNeighbors(v)) local = local && A.triangleNormal(f).dot(frame.b(w) - frame.b(v)) >= 0;
          EXPECT_EQ(frame.compatibleFV(f, v), local);
        }
      for (int e = 0; e < A.numEdges(); ++e)
        for (int ep = 0; ep < B.numEdges(); ++ep)
          if (A.edgeKind(e) == mink::EdgeKind::Reflex || B.edgeKind(ep) == mink::EdgeKind::Reflex) {
            EXPECT_EQ(frame.compatibleEE(e, ep), 0);
          }
    }
}

TEST(Convolution, FacetsFaceOutward) {
  const auto sa = mink_test::uBlock(), sb = mink_test::starPrism();
  const auto A = mink::TriangleMesh<Q>::fromMesh(sa.verticesAs<Q>(), sa.triangles);
  const auto B = mink::TriangleMesh<Q>::fromMesh(sb.verticesAs<Q>(), sb.triangles);
  mink::ConvolutionFrame<Q> frame(A, B);
  frame.place(quarterTurn(), Vq(Q(1), Q(2), Q(3)));
  const auto pairs = mink::allCompatiblePairs(frame);
  int counts[3] = {0, 0, 0};
  for (const auto& c : pairs) {
    std::array<int, 2> poly[4];
    const int n = frame.facetPolygon(c, poly);
    Vq normal;
    switch (c.type) {
      case mink::ConvolutionType::FV: normal = A.triangleNormal(c.featureA); break;
      case mink::ConvolutionType::VF: normal = -(frame.R() * B.triangleNormal(c.featureB)); break;
      case mink::ConvolutionType::EE: {
        const auto ea = A.edgeVertices(c.featureA), eb = B.edgeVertices(c.featureB);
        normal = Q(c.orientation) * (frame.a(ea.second) - frame.a(ea.first)).cross(frame.b(eb.second) - frame.b(eb.first));
        break;
      }
    }
    ++counts[static_cast<int>(c.type)];
    const Vq p0 = frame.m(poly[0][0], poly[0][1]);
    for (int k = 1; k + 1 < n; ++k) {
      const Vq nk = (frame.m(poly[k][0], poly[k][1]) - p0).cross(frame.m(poly[k + 1][0], poly[k + 1][1]) - p0);
      EXPECT_GT(nk.dot(normal), 0) << "type " << static_cast<int>(c.type) << " " << c.featureA << " " << c.featureB;
    }
  }
  EXPECT_GT(counts[0], 0);
  EXPECT_GT(counts[1], 0);
  EXPECT_GT(counts[2], 0);
}

}  // namespace
