// mink/core/defaults.hpp — every default tolerance and threshold of mink, in one place.
//
// Each constant says what it means, its unit and the range in which it is safe.
// Algorithms never hard-code a number; they read these through an options struct
// whose members default to them.
#pragma once

namespace mink {
namespace defaults {

/// Hull and validation tolerance, as a multiple of (unit roundoff) x (scene extent),
/// where the extent is |x|max + |y|max + |z|max of the input points (qhull's and
/// Jolt's convention). A point within this distance of a face plane counts as on it;
/// neighbouring faces whose vertices are within it of one plane are merged.
/// Unit: multiples of eps * extent. Safe range: 4 .. 1e6 (larger merges more, rounds
/// sharp-but-tiny features away). Exact scalars always use 0.
constexpr double kHullToleranceFactor = 64.0;

/// A convex polyhedron with fewer vertices than this answers support queries by
/// hill-climbing its vertex graph and never builds a Dobkin–Kirkpatrick hierarchy.
/// Unit: vertices. Measured crossover: see benchmarks/README section in README.md.
constexpr int kHierarchyMinVertices = 512;

/// Dobkin–Kirkpatrick construction removes independent vertices of degree at most
/// this many per level. Unit: edges. Safe range: 6 .. 12 (the planar-graph bound
/// guarantees a constant fraction of removable vertices for any value >= 6).
constexpr int kHierarchyMaxRemovedDegree = 8;

/// A hierarchy level with at most this many vertices is the top: queries scan it.
/// Unit: vertices. Safe range: 4 .. 64.
constexpr int kHierarchyTopVertices = 16;

}  // namespace defaults
}  // namespace mink
