// tests/hierarchy/hostile_input_test.cpp — hostile input to DKHierarchy<T> and the support
// queries (issue 5): bad options are rejected with a message naming the option and its
// value; NaN, infinite and zero directions (which the hot query path documents as not
// checked) must still terminate and return a valid vertex index, never loop or read out
// of range.
#include "mink/hierarchy/dk_hierarchy.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {

using mink::ConvexPolyhedron;
using V = mink::Vec3<double>;

std::vector<V> spherePoints(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g;
  std::vector<V> p;
  for (int i = 0; i < n; ++i) p.push_back(V(g(rng), g(rng), g(rng)).normalized());
  return p;
}

TEST(HierarchyHostile, BadOptionsNameTheOptionAndValue) {
  const auto P = ConvexPolyhedron<double>::fromPoints(spherePoints(60, 501u));
  struct Case {
    int maxRemovedDegree, topVertices;
    const char* words;
  };
  for (const Case& c : {Case{2, 16, "maxRemovedDegree must be >= 3, got 2"}, Case{-5, 16, "maxRemovedDegree must be >= 3, got -5"},
                        Case{8, 3, "topVertices must be >= 4, got 3"}, Case{8, 0, "topVertices must be >= 4, got 0"}}) {
    SCOPED_TRACE(c.words);
    mink::DKHierarchyOptions o;
    o.maxRemovedDegree = c.maxRemovedDegree;
    o.topVertices = c.topVertices;
    try {
      mink::DKHierarchy<double> h(P, o);
      ADD_FAILURE() << "accepted";
    } catch (const mink::InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find(c.words), std::string::npos) << e.what();
      // checkOptions (what a build without exceptions calls first) gives the same message.
      EXPECT_EQ(mink::DKHierarchy<double>::checkOptions(o).message(), std::string(e.what()));
    }
  }
  EXPECT_FALSE(mink::DKHierarchy<double>::checkOptions(mink::DKHierarchyOptions{}));
}

TEST(HierarchyHostile, NonFiniteAndZeroDirectionsTerminate) {
  // 2000 points: above defaults::kHierarchyMinVertices, so extremeVertex uses the hierarchy.
  const auto P = ConvexPolyhedron<double>::fromPoints(spherePoints(2000, 502u));
  ASSERT_NE(mink::hierarchyOf(P), nullptr);
  const mink::DKHierarchy<double> H(P);
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (const V& d : {V(nan, 0, 0), V(nan, nan, nan), V(inf, 0, 0), V(inf, -inf, 0), V(0, 0, 0), V(-inf, 1, 1)}) {
    SCOPED_TRACE(::testing::Message() << "direction " << d.transpose());
    const int n = P.numVertices();
    for (int v : {P.support(d), P.support(d, n / 2), P.supportBruteForce(d), H.support(d), mink::extremeVertex(P, d),
                  mink::extremeVertex(P, d, 7)}) {
      EXPECT_GE(v, 0);
      EXPECT_LT(v, n);
    }
  }
}

}  // namespace
