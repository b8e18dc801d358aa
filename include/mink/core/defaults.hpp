// mink/core/defaults.hpp — every default tolerance and threshold of mink, in one place.
//
// Each constant says what it means, its unit and the range in which it is safe.
// Algorithms never hard-code a number; they read these through an options struct
// whose members default to them.
#pragma once

namespace mink {
namespace defaults {

/// Shape-construction tolerance, as a multiple of (unit roundoff) x (scene extent),
/// where the extent is |x|max + |y|max + |z|max of the input points (qhull's and Jolt's
/// convention). fromPoints rejects input whose points all lie within this distance of
/// one point, line or plane; fromMesh accepts faces this far from planar and vertices
/// this far above a neighbouring face plane. The hull itself is exact (orient3d) and
/// faces merge only when exactly coplanar. Unit: multiples of eps * extent.
/// Safe range: 4 .. 1e6. Exact scalars always use 0.
constexpr double kHullToleranceFactor = 64.0;

/// A convex polyhedron with fewer vertices than this answers support queries by
/// hill-climbing its vertex graph and never builds a Dobkin–Kirkpatrick hierarchy.
/// Unit: vertices. Measured (benchmarks/README.md; double, ellipsoid point sets, random
/// directions, three runs): the hierarchy's query time falls below a cold hill-climb's
/// from vertex 0 at 48 .. 128 vertices, but by less than 25% up to 512 .. 768 vertices;
/// from 1024 on it is >= 1.3x faster (2x at 4096, 7.7x at 100k). Its build (0.2 .. 0.3x
/// the hull build since levels are made by filling holes, ~270 bytes per vertex; 2.1 ..
/// 2.8x when every level was re-hulled) pays back after ~5e3 such queries at 1024
/// vertices (benchmarks/run_foundation.sh). Safe range: 16 .. 1e5 (any value is correct;
/// only speed and memory change).
constexpr int kHierarchyMinVertices = 1024;

/// A convex polyhedron with at least this many vertices numbers its vertices and faces in
/// Morton order of their points (core/detail/spatial_order.hpp) instead of the hull's
/// order, so that support queries and hierarchy descents read nearby memory. Below it the
/// arrays fit in cache and the ids keep the order of the faces. Unit: vertices.
/// Measured (mink_mdd_bench --sections scaling, ellipsoid pairs; README): cold MDD queries
/// 1.5 - 1.8x faster at 100k vertices, coherent ones 2.2x, cold 1.15 - 1.3x at 10k.
/// Safe range: any (only ids and speed change).
constexpr int kSpatialOrderMinVertices = 1024;

/// A support query on a shape with a hierarchy, given a vertex that was the support of a
/// nearby direction (an iterative step's last answer), first hill-climbs from it on the
/// shape's graph for at most this many moves, and descends the hierarchy only if the
/// climb has not ended by then (DKHierarchy::supportFrom). Unit: moves (each reads one
/// vertex's neighbours). Safe range: >= 0 (0: every such query descends; any value is
/// correct, only speed changes). Measured (mink_mdd_bench --sections scaling,
/// ellipsoid pairs, cold MDD queries, 0 against 8, three runs each): 10k vertices 21.1 -
/// 23.8 -> 17.4 - 18.0 us; 100k 50 - 58 -> 51 - 53 us (within the runs' spread: there a
/// third of the portal's refinement directions are more than 16 moves from the last).
constexpr int kHierarchyClimbMoves = 8;

/// The exit portal's secant steps (mdd/detail/exit_portal.hpp) interpolate M's normal
/// from the corners' support directions: they pay on finely faceted smooth shapes and
/// cost on large flat faces and high-degree vertices (a 1,024-gon prism's generic
/// contacts took 42 portal steps with them against 11 without, a cone's apex of degree
/// 1,024 44 against 15). They run only where both shapes have a hierarchy whose shape
/// has faces of at most kSecantMaxFaceVertices vertices and vertices of at most
/// kSecantMaxDegree edges. Units: vertices, edges. Any value is correct (only speed
/// changes); a triangulated sphere or ellipsoid has faces of 3 and degrees near 6.
constexpr int kSecantMaxFaceVertices = 8;
constexpr int kSecantMaxDegree = 32;

/// A contact polygon of at least kConvexCycleMinPoints points (a support set that is one
/// face of a shape, the vertices of a facet of M) is first tried as a strictly convex
/// polygon in the order given (mdd/detail/difference_polygon.hpp, convexCycleOrientation:
/// exact turns, O(n)); only where that fails is it sorted for a hull (O(n log n)). Two
/// resting 1,024-gon caps spent 38% of a query in those sorts. Units: points. Any value
/// is correct (only speed changes): below it the sort is as fast as the check.
constexpr int kConvexCycleMinPoints = 16;

/// Dobkin–Kirkpatrick construction removes independent vertices of degree at most
/// this many per level. Unit: edges. Safe range: 6 .. 12 (the planar-graph bound
/// guarantees a constant fraction of removable vertices for any value >= 6). Measured at
/// n = 100k: 6, 8, 10, 12 give 30 +- 2 levels and query times within 10% of each other.
constexpr int kHierarchyMaxRemovedDegree = 8;

/// A hierarchy level with at most this many vertices is the top: queries scan it.
/// Unit: vertices. Safe range: 4 .. 64. Measured at n = 100k: 8 .. 64 give query times
/// within 10% of each other (fewer levels against a longer scan).
constexpr int kHierarchyTopVertices = 16;

/// Poses: a rotation R is accepted when every entry of R^T R - I is at most this (or
/// 100 eps of the scalar, if larger) and det R > 0. Unit: none. Safe range: 1e-12 ..
/// 1e-3. Exact scalars require R^T R == I exactly.
constexpr double kRotationTolerance = 1e-6;

/// MDD: |translation| at or below this many (unit roundoff) x (scene size) counts as
/// Touching for inexact scalars; the scene size is extent(P) + extent(Q) + |t_rel|
/// (t_rel: Q's position in P's frame). Unit: multiples of eps * scene size.
/// Safe range: 16 .. 1e6. Exact scalars always use 0.
constexpr double kMddTouchToleranceFactor = 256.0;

/// MDD: the three phases of one search (one direction) evaluate at most this many times
/// (faces(P) + faces(Q) + 64) candidate faces of M before reporting
/// MddStatus::IterationLimit (the exhaustive check, when used, is bounded by its own
/// faces(P) + faces(Q) + edges(P) * edges(Q): see kMddExhaustivePairs). Unit: multiple of
/// the face counts.
/// Safe range: >= 2 (the FV and VF walks evaluate each face at most once).
constexpr long long kMddVisitFactor = 4;

/// MDD: the fallbacks for a search that cannot answer (the exhaustive check of every FV,
/// VF and EE face of M, and the chord of M by clipping the line against all their planes)
/// visit every edge pair of P and Q, which is quadratic in the sizes: they run only where
/// edges(P) * edges(Q) is at most this many; above it such a query reports
/// MddStatus::IterationLimit (and intersects() answers true). 2^24 pairs: two shapes of
/// about 1400 vertices, or 100k vertices against a box (one pass over 15M pairs took
/// 0.4 s on the project's machine; a fallback makes one to three).
/// Unit: edge pairs. Safe range: >= 0 (0: never fall back).
constexpr long long kMddExhaustivePairs = 1LL << 24;

/// MDD: the 2-D portal refinement of the centre-of-duality step gives up after this many
/// iterations times (vertices(P) + vertices(Q) + 16). Unit: multiple. Safe range: >= 1.
constexpr long long kMddPortalFactor = 2;

/// MDD: support queries the exit-portal estimate (mdd/detail/exit_portal.hpp) may make before
/// the searches start from its best normal so far. It only seeds the searches, so a cap
/// costs time, never correctness. Unit: support queries on M. Safe range: >= 4.
constexpr int kMddExitPortalSteps = 48;

/// MDD: at the exit-portal estimate's support vertices, the EE faces tried first (before
/// any search) pair this many edges at each vertex: those whose Gauss arcs pass nearest
/// the estimate's normal. All deg(P) x deg(Q) pairs were tried before, a million at the
/// apexes of two 1024-gon cones. Only the start of the searches depends on it. Unit:
/// edges per vertex. Safe range: 1 .. 16 (vertices of degree up to it try every pair).
constexpr int kMddPortalEdgeCandidates = 6;

/// MDD, SEARCH-EE: at a vertex pair whose degrees both exceed this, the EE faces are
/// found by chasing the two Gauss regions' boundaries (O(deg + deg) pairs tested,
/// mdd/detail/region_crossings.hpp) instead of testing every pair; below it all pairs are
/// cheaper, and with one degree at most this, all pairs are linear in the other. Both
/// find the same faces. Unit: edges at a vertex. Safe range: >= 2.
constexpr int kMddChaseMinDegree = 6;

/// MDD, inexact scalars: an edge pair of P and Q whose directions make a sine below this
/// many eps is treated as parallel (no EE face): its cross product is rounding noise.
/// Unit: multiples of eps. Safe range: 4 .. 1e4.
constexpr double kMddParallelEdgeFactor = 64.0;

/// MDD, inexact scalars: an edge whose two unit face normals have a cross product shorter
/// than this (a dihedral angle within about this many radians of 180°) has its Gauss-map
/// arc's plane taken from the edge direction rather than from its rounded normals, whose
/// plane is tilted by up to 2 eps / |cross|. Unit: length of the cross product of two unit
/// normals (sine of the exterior angle). Safe range: 64 eps .. 0.1 (any value is exact
/// on the numbers used; it only chooses the better-conditioned plane).
constexpr double kMddSharpEdgeCross = 1.0 / 1024.0;

/// MDD, inexact scalars, witnesses: the barycentric weights of the origin in a triangle of
/// a contact polygon (mdd/detail/contact_set.hpp) below −this are not rounding of a point
/// on the triangle's side but the noise of a sliver triangle (three points collinear to
/// rounding): such weights are repaired (clamped, or the nearest side) or the triangle
/// gives no location. Unit: barycentric weight (dimensionless). Safe range: 1e-8 .. 0.1.
constexpr double kMddWitnessWeightSlack = 1.0 / 1024.0;

/// MDD, inexact scalars, witnesses: weights are accepted when their combination of the
/// polygon's points rebuilds the origin to this many eps times the points' largest
/// coordinate; otherwise a repaired combination that does better replaces them.
/// Unit: multiples of eps × coordinate size. Safe range: 4 .. 1e4.
constexpr double kMddWitnessResidualFactor = 16.0;

/// MDD, inexact scalars, witnesses: negative weights left on a contact polygon of at most
/// this many points are replaced by the best non-negative combination of one, two or three
/// of its points (every triple is tried: cubic in this number). Unit: points.
/// Safe range: 3 .. 64 (larger polygons keep their weights; witnesses stay within the
/// facet check's slack of M either way).
constexpr int kMddWitnessRepairMaxPoints = 32;

/// MDD, inexact scalars, witnesses of an EE contact: the line's crossing of the two edges'
/// parallelogram, in edge parameters (0 .. 1 along each edge), is used when it lies this
/// far outside [0, 1] at most (then clamped to the edges); farther, the line crossed a
/// coplanar neighbour of the facet and the facet check's witnesses stay. Unit: edge
/// parameter (dimensionless). Safe range: 1e-12 .. 1e-3.
constexpr double kMddEdgeWitnessSlack = 1e-6;

/// MDD, inexact scalars: a face of M that the line of s meets at a sine below this is not
/// accepted on its certificate alone (the line crossing the face's own polygon, without
/// a search: cached faces and the faces around the exit-portal estimate); the searches
/// and the facet check decide instead. Its line parameter k / (N·s) carries the rounding
/// of the scene times 1 / sine. Unit: sine of the angle between s and the face plane.
/// Safe range: 0 .. 0.1 (smaller accepts more faces without a search).
constexpr double kMddCertificateSine = 1.0 / 256.0;

/// Mesh point location (mesh/point_in_mesh.hpp): rays cast from one point before the
/// answer is PointLocation::Undecided. A ray is cast again, in another direction, only
/// when it meets an edge or a corner of the mesh exactly (or lies in a triangle's plane
/// across it); each direction has a different irrational-like slant, so for any input not
/// built against this sequence the first or second ray decides. Unit: rays. Safe range:
/// 6 .. 1000 (any value is correct; a larger one only makes Undecided rarer).
constexpr int kPointInMeshMaxRays = 64;

/// CPD, Phong projection (cpd/phong_projection.hpp): Definition 1's λ_i >= 0 is accepted
/// down to -this. Unit: barycentric coordinate (dimensionless). Safe range: 0 .. 1e-3
/// (larger admits points past a triangle's edge, with that triangle's normals).
constexpr double kPhongBarycentricTolerance = 1e-9;
/// CPD, Phong projection: Newton steps per triangle before it is given up. From the
/// barycentre of a triangle whose vertex normals are within Theorem 3's bound Newton
/// converges in 3 .. 6 steps (quadratically). Unit: iterations. Safe range: 4 .. 100.
constexpr int kPhongNewtonIterations = 30;
/// CPD, Algorithm 2 (cpd/continuous_penetration_depth.hpp): the search ball's radius is
/// alpha * |q| around the current candidate q (the paper's alpha, section 6.1).
/// Unit: dimensionless. Safe range: 0.05 .. 2 (larger balls cost more triangles per step).
constexpr double kCpdAlpha = 0.3;
/// CPD, Algorithm 2: the factor by which the ball grows when the candidate does not
/// improve (the paper's beta). Unit: dimensionless. Safe range: 1.2 .. 10.
constexpr double kCpdBeta = 2.0;
/// CPD, Algorithm 2: balls built per query before the best candidate is returned as
/// CpdStatus::Approximate. Unit: iterations. Safe range: 1 .. 1000.
constexpr int kCpdMaxIterations = 24;
/// CPD, Algorithm 2: the ball grows (by beta) to at most this times |q0|, the start's
/// depth; then the best candidate is returned as Approximate. Without a cap the growth
/// reaches Phong projections far deeper than the start where none lies near it (on the
/// paper's cone/axes scene: depth 3.7 against a start and a Euclidean depth of 0.31, and
/// 9 s for the frame). Unit: dimensionless. Safe range: 0.5 .. 10 (larger finds farther
/// projections, at the cost of bigger balls).
constexpr double kCpdMaxRadiusFactor = 2.0;
/// CPD, initialisation without a previous frame: bisection steps per direction for the
/// first exit of the origin from M (each one mesh-overlap test). The exit only seeds the
/// search ball, so 2^-30 of the scene's size is ample. Unit: steps. Safe range: 8 .. 60.
constexpr int kCpdExitBisectionSteps = 30;

}  // namespace defaults
}  // namespace mink
