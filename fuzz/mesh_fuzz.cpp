// fuzz/mesh_fuzz.cpp — libFuzzer target for mink's mesh layer and CPD's local Minkowski
// sum on hostile input (issue 14: "open, non-manifold, inverted, NaN, degenerate — a clear
// InvalidInput, never a crash").
//
// Each input is decoded (Decoder below; reads past the end give 0) into:
//   - mesh A: either random (3 .. 16 vertices in one coordinate style: small-integer grid
//     full of duplicates and coplanar points, int8, scaled int16, raw IEEE doubles, a table
//     of specials with NaN / ±Inf / denormals / 1e±300, grid + 2^-40 offsets; 1 .. 32
//     triangles of random indices, some out of range or negative), or structured: a closed
//     tetrahedron, octahedron, box, torus grid (n × m, double or lattice coordinates) or
//     two components, scaled by 2^e and moved on the lattice, then edited (a coordinate
//     set to a special or a raw double, nudged by 2^-40, snapped onto or half-way to
//     another vertex, reflected) and mutated (a triangle flipped, dropped, duplicated,
//     duplicated flipped, given an out-of-range or another in-range corner; all flipped;
//     corners rotated, triangles swapped, an unused vertex added);
//   - mesh B: a box or octahedron at A's scale, another decoded mesh, or A itself;
//   - poses of A and B (identity, the 48 signed permutations, unit and non-unit
//     quaternions, rotations nudged around the 1e-6 acceptance threshold, raw specials,
//     NaN), a small motion for a second update, and a ball (centre, radius: 0, negative,
//     NaN, Inf, huge, denormal, raw doubles).
//
// Accepted outcomes: mink::InvalidInput, or a result that passes the checks below.
// Anything else fails: a crash, a sanitizer report, another exception, a hang.
//   1. fromMesh: an accepted mesh is verified independently (exactly, in __float128
//      expansions): vertices finite and within ScalarTraits::largestCoordinate(), indices
//      in range, every vertex used, every edge used by exactly two triangles in opposite
//      directions, the triangles at each vertex one fan, no triangle with collinear
//      corners, every connected component of positive signed volume, and the counts
//      (vertices, triangles, edges, components) right. An unedited structured mesh (only
//      corner rotations and triangle swaps, scale 2^-900 .. 2^280) is valid and must be
//      accepted.
//   2. LocalMinkowskiSum::update (only on meshes without self-intersection, the
//      precondition of the mesh layer, established by findSelfIntersection): it must throw
//      InvalidInput for a non-finite centre, a radius <= 0 or non-finite, or a pose that is
//      not rigid, and must not for valid ones (poses within a factor 2 of the 1e-6
//      orthonormality threshold may go either way). A returned patch must have finite
//      vertices, indices in range, one pair per triangle, and every triangle must meet
//      the ball (distance from the centre, long double, at most radius (1 + 1e-9) plus the
//      rounding of the scene and of the poses). The methods (BruteForce, SphereTree,
//      BoxTrees, ConvexMaps; BruteForce only when both meshes have at most 40 triangles) must
//      gather the same convolution facets and return the same number of triangles with
//      the same total area (1e-9 relative). update() runs twice, the second time after a
//      small motion, which exercises ConvexMaps' coherent walk from the last cells and
//      BoxTrees' placing B anew (SphereTree, rebuilt on every call, only the first time).
//   3. The CPD query (ContinuousPenetrationDepth over both poses, and penetrationDepth) on
//      scenes of at most 400 triangle pairs, 8 balls: InvalidInput exactly as update();
//      Separated with depth 0 whenever MeshOverlap finds no common point; otherwise a
//      finite positive depth, a unit direction, point = depth · direction, and where CPD
//      says Penetrating, a normal whose line passes through the origin (1e-6 of the depth
//      plus (1e-12 + 4e)·L: the rounding of a scene of size L, poses e off orthonormal).
// No check is bounded: the last open bugs' bounds (a ball's radius capped on larger meshes,
// ConvexMaps allowed to miss facets of collapsed placements) were lifted on 2026-12-06
// with their fixes (fuzz/README.md).

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include <mink/cpd/local_minkowski_sum.hpp>
#include <mink/mink.hpp>

#include "fuzz_decoder.hpp"

namespace {

using V = mink::Vec3<double>;
using M3 = mink::Mat3<double>;
using Tri = std::array<int, 3>;
using Mesh = mink::TriangleMesh<double>;
using LD = long double;
using VL = Eigen::Matrix<LD, 3, 1>;

using mink_fuzz::Decoder;  // fuzz_decoder.hpp

// A power-of-two exponent: mostly -7 .. 7, one time in 8 up to ±1016 (overflow, denormals).
int exponent(Decoder& in) {
  const int b = in.i8();
  return in.u8() % 8 == 7 ? 8 * b : b % 8;
}

double coordinate(Decoder& in, int style, int e) {
  switch (style) {
    case 0: return std::ldexp(static_cast<double>(static_cast<int>(in.u8() % 5) - 2), e);  // ties
    case 1: return std::ldexp(static_cast<double>(in.i8()), e);
    case 2: return std::ldexp(static_cast<double>(in.i16()), e - 8);
    case 3: return in.f64();
    case 4: return (in.u8() & 1) ? in.special() : std::ldexp(static_cast<double>(static_cast<int>(in.u8() % 5) - 2), e);
    default: {  // grid plus a tiny offset: nearly coplanar, nearly collinear
      const double grid = static_cast<int>(in.u8() % 5) - 2;
      return std::ldexp(grid + std::ldexp(static_cast<double>(in.i8()), -40), e);
    }
  }
}

V vector3(Decoder& in, int style, int e) {
  const double x = coordinate(in, style, e);
  const double y = coordinate(in, style, e);
  const double z = coordinate(in, style, e);
  return V(x, y, z);
}

// An index for a mesh of nv vertices: mostly in range, from byte 240 on a bad one.
int index(Decoder& in, int nv) {
  const int b = in.u8();
  if (b < 240) return b % nv;
  const int bad[8] = {-1, nv, nv + 1, -nv, INT_MIN, INT_MAX, 255, -2};
  return bad[(b - 240) % 8];
}

// ---------------------------------------------------------------------------------------
// Closed base shapes, counter-clockwise seen from outside.
struct RawMesh {
  std::vector<V> vertices;
  std::vector<Tri> triangles;
  const char* origin = "";
  bool mustAccept = false;  // valid by construction: fromMesh must accept it
};

RawMesh tetrahedron() {
  return {{V(0, 0, 0), V(2, 0, 0), V(0, 2, 0), V(0, 0, 2)}, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}, "tetrahedron"};
}

RawMesh octahedron() {
  RawMesh m{{V(1, 0, 0), V(-1, 0, 0), V(0, 1, 0), V(0, -1, 0), V(0, 0, 1), V(0, 0, -1)}, {}, "octahedron"};
  for (int sx = 0; sx < 2; ++sx)
    for (int sy = 0; sy < 2; ++sy)
      for (int sz = 0; sz < 2; ++sz) {
        const int x = sx, y = 2 + sy, z = 4 + sz;
        // (X, Y, Z) is counter-clockwise from outside when the octant has an even number
        // of negative axes.
        if ((sx + sy + sz) % 2 == 0)
          m.triangles.push_back({x, y, z});
        else
          m.triangles.push_back({x, z, y});
      }
  return m;
}

RawMesh box() {
  RawMesh m{{}, {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                 {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}},
            "box"};
  for (int i = 0; i < 8; ++i) m.vertices.push_back(V(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1));
  return m;
}

// Ring of n sections around z (radius 3), tube of m corners (radius 1); lattice: the
// coordinates times 4, rounded to integers.
RawMesh torus(int n, int m, bool lattice) {
  RawMesh t{{}, {}, lattice ? "lattice torus" : "torus"};
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double u = 2 * pi * i / n, v = 2 * pi * j / m;
      V p((3 + std::cos(v)) * std::cos(u), (3 + std::cos(v)) * std::sin(u), std::sin(v));
      if (lattice) p = (4 * p).array().round().matrix();
      t.vertices.push_back(p);
    }
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const int a = i * m + j, b = ((i + 1) % n) * m + j, c = ((i + 1) % n) * m + (j + 1) % m, d = i * m + (j + 1) % m;
      t.triangles.push_back({a, b, c});
      t.triangles.push_back({a, c, d});
    }
  return t;
}

RawMesh twoComponents() {
  RawMesh m = box();
  const RawMesh o = octahedron();
  const int base = static_cast<int>(m.vertices.size());
  for (const V& v : o.vertices) m.vertices.push_back(v + V(4, 0, 0));
  for (const Tri& t : o.triangles) m.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  m.origin = "box + octahedron";
  return m;
}

RawMesh decodeMesh(Decoder& in, int& unitExp) {
  const int kind = in.u8() % 8;
  if (kind < 2) {  // random vertices and triangles
    RawMesh m{{}, {}, "random"};
    const int nv = 3 + in.u8() % 14;
    const int style = in.u8() % 6;
    const int e = exponent(in);
    unitExp = e;
    for (int i = 0; i < nv; ++i) {
      const std::uint8_t dup = in.u8();
      if (i > 0 && dup % 8 == 0)
        m.vertices.push_back(m.vertices[dup % i]);  // exact duplicate
      else
        m.vertices.push_back(vector3(in, style, e));
    }
    const int nt = 1 + in.u8() % 32;
    for (int t = 0; t < nt; ++t) {
      const int a = index(in, nv), b = index(in, nv), c = index(in, nv);
      m.triangles.push_back({a, b, c});
    }
    return m;
  }
  RawMesh m;
  switch (kind) {
    case 2: m = tetrahedron(); break;
    case 3: m = octahedron(); break;
    case 4: m = box(); break;
    case 5:
    case 6: {
      const int n = 3 + in.u8() % 4, k = 3 + in.u8() % 2;
      m = torus(n, k, kind == 6);
      break;
    }
    default: m = twoComponents(); break;
  }
  const int e = exponent(in);
  unitExp = e;
  V offset;
  for (int a = 0; a < 3; ++a) offset[a] = static_cast<int>(in.u8() % 5) - 2;
  for (V& v : m.vertices)
    for (int a = 0; a < 3; ++a) v[a] = std::ldexp(v[a] + offset[a], e);
  // The torus' coordinates have 53 bits: below 2^-900 they would lose them to denormals.
  m.mustAccept = e >= -900 && e <= 280;
  const int nv = static_cast<int>(m.vertices.size());
  const int edits = in.u8() % 4;
  for (int k = 0; k < edits; ++k) {
    const int v = in.u8() % nv, w = in.u8() % nv, op = in.u8() % 6;
    const int a = in.u8() % 3;
    m.mustAccept = false;
    switch (op) {
      case 0: m.vertices[v][a] = in.special(); break;
      case 1: m.vertices[v][a] += std::ldexp(static_cast<double>(in.i8()), e - 40); break;
      case 2: m.vertices[v] = m.vertices[w]; break;
      case 3: m.vertices[v] = 0.5 * (m.vertices[v] + m.vertices[w]); break;
      case 4: m.vertices[v][a] = in.f64(); break;
      default: m.vertices[v][a] = -m.vertices[v][a]; break;
    }
  }
  const int mutations = in.u8() % 4;
  for (int k = 0; k < mutations; ++k) {
    const int nt = static_cast<int>(m.triangles.size());
    const int op = in.u8() % 10, t = in.u8() % std::max(nt, 1), c = in.u8() % 3;
    if (nt == 0) break;
    Tri& tri = m.triangles[t];
    switch (op) {
      case 0: std::swap(tri[1], tri[2]); m.mustAccept = false; break;  // one flipped: inconsistent
      case 1:                                                           // all flipped: inward
        for (Tri& s : m.triangles) std::swap(s[1], s[2]);
        m.mustAccept = false;
        break;
      case 2: m.triangles.erase(m.triangles.begin() + t); m.mustAccept = false; break;  // open
      case 3: m.triangles.push_back(tri); m.mustAccept = false; break;                  // non-manifold
      case 4:                                                                            // folded extra
        m.triangles.push_back({tri[0], tri[2], tri[1]});
        m.mustAccept = false;
        break;
      case 5:  // out of range or negative
        tri[c] = (in.u8() & 1) ? nv + in.u8() % 4 : -1 - in.u8() % 4;
        m.mustAccept = false;
        break;
      case 6: tri[c] = in.u8() % nv; m.mustAccept = false; break;
      case 7: std::rotate(tri.begin(), tri.begin() + 1, tri.end()); break;  // same triangle
      case 8: std::swap(tri, m.triangles[c % nt]); break;                    // same mesh
      default:                                                               // unused vertex
        m.vertices.push_back(V(0, 0, 0));
        m.mustAccept = false;
        break;
    }
  }
  return m;
}

// ---------------------------------------------------------------------------------------
// Poses and the ball.
Eigen::Quaterniond quaternion(Decoder& in) {
  const double w = in.i8(), x = in.i8(), y = in.i8(), z = in.i8();
  const Eigen::Quaterniond q(w, x, y, z);
  return q.coeffs().squaredNorm() == 0 ? Eigen::Quaterniond::Identity() : q;
}

// Kind 0 (zero bytes) gives A the identity and B a fixed generic rotation: exact face-on
// contacts of lattice shapes (coplanar facets everywhere) take the trimming's exact path,
// 10 to 100 times slower, so they are asked for (kind 7), not the default.
mink::Pose<double> decodePose(Decoder& in, int unitExp, bool isB) {
  mink::Pose<double> p;
  const int kind = in.u8() % 8;
  switch (kind) {
    case 0:
      if (isB) p.rotation = Eigen::Quaterniond(5, 1, -2, 3).normalized().toRotationMatrix();
      break;
    case 1: {  // signed permutation: exact 90° rotations (and reflections, det -1)
      const int code = in.u8() % 48;
      static const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
      const int* pm = perms[code % 6];
      M3 R = M3::Zero();
      for (int r = 0; r < 3; ++r) R(r, pm[r]) = ((code / 6) >> r) & 1 ? -1.0 : 1.0;
      p.rotation = R;
      break;
    }
    case 2:
    case 3: {  // quaternion; kind 3 left unnormalised (not orthonormal unless |q| = 1)
      Eigen::Quaterniond q = quaternion(in);
      if (kind == 2) q.normalize();
      p.rotation = q.toRotationMatrix();
      break;
    }
    case 4: {  // raw entries: mostly rejected
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) p.rotation(r, c) = in.special();
      break;
    }
    case 5: {  // a rotation nudged around the 1e-6 acceptance threshold
      Eigen::Quaterniond q = quaternion(in);
      q.normalize();
      p.rotation = q.toRotationMatrix();
      const int e = in.u8();
      p.rotation(e % 3, (e / 3) % 3) += std::ldexp(1.0, -(10 + in.u8() % 40));
      break;
    }
    case 6: {  // a NaN somewhere
      const int e = in.u8() % 12;
      if (e < 9)
        p.rotation(e % 3, e / 3) = std::numeric_limits<double>::quiet_NaN();
      else
        p.translation[e - 9] = std::numeric_limits<double>::quiet_NaN();
      break;
    }
    default: break;  // 7: identity
  }
  const int style = in.u8() % 6;
  p.translation += vector3(in, style == 3 ? 4 : style, unitExp);
  return p;
}

// A small rigid motion: a rotation by about 2^-9 rad per unit of three int8, a shift of
// 2^-7 units per int8.
mink::Pose<double> moved(const mink::Pose<double>& p, Decoder& in, int unitExp) {
  // Read in order (a function's arguments are evaluated in an unspecified order: g++ and
  // clang decoded the same bytes to different rotations).
  const double x = std::ldexp(in.i8(), -10), y = std::ldexp(in.i8(), -10), z = std::ldexp(in.i8(), -10);
  Eigen::Quaterniond q(1.0, x, y, z);
  q.normalize();
  mink::Pose<double> r = p;
  r.rotation = q.toRotationMatrix() * p.rotation;
  for (int a = 0; a < 3; ++a) r.translation[a] += std::ldexp(static_cast<double>(in.i8()), unitExp - 7);
  return r;
}

// ---------------------------------------------------------------------------------------
// What the current input decoded to, printed exactly when a check fails.
struct Scene {
  const RawMesh* raw[2] = {nullptr, nullptr};
  const char* bKind = "";
  mink::Pose<double> poses[4];  // A, B at the first update; A, B at the second
  V centre = V::Zero();
  double radius = 0;
  int step = -1;
} gScene;

void printMesh(const char* name, const RawMesh* m) {
  if (!m) return;
  std::fprintf(stderr, "%s (%s, %zu vertices, %zu triangles):\n", name, m->origin, m->vertices.size(),
               m->triangles.size());
  for (std::size_t i = 0; i < m->vertices.size(); ++i) {
    const V& p = m->vertices[i];
    std::fprintf(stderr, "  v%zu  %a %a %a   (%.17g %.17g %.17g)\n", i, p[0], p[1], p[2], p[0], p[1], p[2]);
  }
  std::fprintf(stderr, "  triangles:");
  for (const Tri& t : m->triangles) std::fprintf(stderr, " {%d %d %d}", t[0], t[1], t[2]);
  std::fprintf(stderr, "\n");
}

void printPose(const char* name, const mink::Pose<double>& pose) {
  std::fprintf(stderr, "%s: rotation rows", name);
  for (int r = 0; r < 3; ++r)
    std::fprintf(stderr, " [%.17g %.17g %.17g]", pose.rotation(r, 0), pose.rotation(r, 1), pose.rotation(r, 2));
  std::fprintf(stderr, " translation [%.17g %.17g %.17g]\n", pose.translation[0], pose.translation[1],
               pose.translation[2]);
}

void printScene() {
  printMesh("A", gScene.raw[0]);
  if (gScene.raw[1] && gScene.raw[1] != gScene.raw[0]) printMesh("B", gScene.raw[1]);
  std::fprintf(stderr, "B is %s\n", gScene.bKind);
  if (gScene.step >= 0) {
    printPose("poseA (update 1)", gScene.poses[0]);
    printPose("poseB (update 1)", gScene.poses[1]);
    printPose("poseA (update 2)", gScene.poses[2]);
    printPose("poseB (update 2)", gScene.poses[3]);
    std::fprintf(stderr, "ball: centre %a %a %a (%.17g %.17g %.17g), radius %a (%.17g); failing update %d\n",
                 gScene.centre[0], gScene.centre[1], gScene.centre[2], gScene.centre[0], gScene.centre[1],
                 gScene.centre[2], gScene.radius, gScene.radius, gScene.step + 1);
  }
}

[[noreturn]] void fail(const std::string& what) {
  std::fprintf(stderr, "\n*** mink fuzz mismatch: %s\n", what.c_str());
  printScene();
  std::fflush(stderr);
  std::abort();
}

// MINK_FUZZ_VERBOSE=1: print every decoded scene and each update's outcome (replaying).
const bool gVerbose = std::getenv("MINK_FUZZ_VERBOSE") != nullptr;

// ---------------------------------------------------------------------------------------
// Exact signs in __float128 (113-bit significand, exponent to ±16382): a product of two
// doubles is exact, and so is TwoSum of any two such values (no underflow: the smallest
// products of doubles, 1e-970 for three factors, are far inside the range). Sums are
// accumulated in a non-overlapping expansion (Shewchuk 1997, Grow-Expansion with zero
// elimination): it is zero iff the exact sum is, and its last component has its sign.
using Q = __float128;

void growExpansion(std::vector<Q>& e, Q b) {
  std::size_t k = 0;
  for (std::size_t i = 0; i < e.size(); ++i) {
    const Q s = b + e[i];
    const Q bv = s - b;
    const Q err = (b - (s - bv)) + (e[i] - bv);
    if (err != 0) e[k++] = err;
    b = s;
  }
  e.resize(k);
  if (b != 0) e.push_back(b);
}

// a * b * c into e exactly: a * b is exact in Q; split into 56 + 57 bits (Veltkamp, 2^57 + 1)
// so that each part times c (53 bits) is exact.
void addTripleProduct(std::vector<Q>& e, double a, double b, double c, int sign) {
  const Q p = static_cast<Q>(a) * static_cast<Q>(b);
  const Q split = static_cast<Q>(144115188075855873.0) /* 2^57 + 1 */;
  const Q t = split * p;
  const Q hi = t - (t - p);
  const Q lo = p - hi;
  growExpansion(e, sign * (hi * static_cast<Q>(c)));
  growExpansion(e, sign * (lo * static_cast<Q>(c)));
}

int expansionSign(const std::vector<Q>& e) { return e.empty() ? 0 : (e.back() > 0 ? 1 : -1); }

// Exactly: are a, b, c collinear ((b − a) × (c − a) = 0)?
bool collinear(const V& a, const V& b, const V& c) {
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    // (b_i − a_i)(c_j − a_j) − (b_j − a_j)(c_i − a_i), expanded; the a_i a_j terms cancel.
    const double terms[6][2] = {{b[i], c[j]}, {b[i], -a[j]}, {-a[i], c[j]}, {-b[j], c[i]}, {b[j], a[i]}, {a[j], c[i]}};
    std::vector<Q> e;
    for (const auto& t : terms) growExpansion(e, static_cast<Q>(t[0]) * static_cast<Q>(t[1]));
    if (!e.empty()) return false;
  }
  return true;
}

// Exact sign of Σ det[a, b, c] over the triangles `which` (six times the signed volume).
int volumeSign(const std::vector<V>& x, const std::vector<Tri>& tris, const std::vector<int>& which) {
  static const int perm[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {1, 0, 2}, {2, 1, 0}};
  static const int sgn[6] = {1, 1, 1, -1, -1, -1};
  std::vector<Q> e;
  for (int t : which) {
    const V& a = x[tris[t][0]];
    const V& b = x[tris[t][1]];
    const V& c = x[tris[t][2]];
    for (int p = 0; p < 6; ++p) addTripleProduct(e, a[perm[p][0]], b[perm[p][1]], c[perm[p][2]], sgn[p]);
  }
  return expansionSign(e);
}

// ---------------------------------------------------------------------------------------
// 1. An accepted mesh, verified against the input it was built from.
void verifyMesh(const Mesh& mesh, const RawMesh& raw, const char* name) {
  const std::string who = std::string("fromMesh accepted ") + name + ", but ";
  const std::vector<V>& x = raw.vertices;
  const std::vector<Tri>& tris = raw.triangles;
  const int nv = static_cast<int>(x.size()), nt = static_cast<int>(tris.size());
  if (nt == 0) fail(who + "it has no triangle");
  const double big = mink::ScalarTraits<double>::largestCoordinate();
  for (int v = 0; v < nv; ++v)
    for (int a = 0; a < 3; ++a)
      if (!std::isfinite(x[v][a]) || std::fabs(x[v][a]) > big)
        fail(who + "vertex " + std::to_string(v) + " is not finite or out of range");
  std::vector<int> used(static_cast<std::size_t>(nv), 0);
  std::map<std::pair<int, int>, int> directed;
  for (int t = 0; t < nt; ++t)
    for (int i = 0; i < 3; ++i) {
      const int a = tris[t][i], b = tris[t][(i + 1) % 3];
      if (a < 0 || a >= nv) fail(who + "triangle " + std::to_string(t) + " has index " + std::to_string(a));
      if (a == b) fail(who + "triangle " + std::to_string(t) + " repeats a corner");
      ++used[a];
      ++directed[{a, b}];
    }
  for (int v = 0; v < nv; ++v)
    if (!used[v]) fail(who + "vertex " + std::to_string(v) + " is unused");
  for (const auto& [ab, n] : directed) {
    const auto back = directed.find({ab.second, ab.first});
    if (n != 1 || back == directed.end() || back->second != 1)
      fail(who + "edge " + std::to_string(ab.first) + "-" + std::to_string(ab.second) +
           " is not used once in each direction");
  }
  // One fan per vertex: the link edges x -> y of the triangles (v, x, y) form one cycle.
  std::vector<std::map<int, int>> link(static_cast<std::size_t>(nv));
  for (const Tri& t : tris)
    for (int i = 0; i < 3; ++i) link[t[i]][t[(i + 1) % 3]] = t[(i + 2) % 3];
  for (int v = 0; v < nv; ++v) {
    const auto& l = link[v];
    int x0 = l.begin()->first, y = x0, steps = 0;
    do {
      const auto it = l.find(y);
      if (it == l.end()) fail(who + "the link of vertex " + std::to_string(v) + " is open");
      y = it->second;
      ++steps;
    } while (y != x0 && steps <= static_cast<int>(l.size()));
    if (steps != static_cast<int>(l.size()))
      fail(who + "vertex " + std::to_string(v) + " has more than one fan of triangles");
  }
  for (int t = 0; t < nt; ++t)
    if (collinear(x[tris[t][0]], x[tris[t][1]], x[tris[t][2]]))
      fail(who + "triangle " + std::to_string(t) + " has collinear corners (zero area)");
  // Components: triangles joined across edges (union-find over the edge map).
  std::vector<int> parent(static_cast<std::size_t>(nt));
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int t) {
    while (parent[t] != t) t = parent[t] = parent[parent[t]];
    return t;
  };
  std::map<std::pair<int, int>, int> owner;
  for (int t = 0; t < nt; ++t)
    for (int i = 0; i < 3; ++i) owner[{tris[t][i], tris[t][(i + 1) % 3]}] = t;
  for (int t = 0; t < nt; ++t)
    for (int i = 0; i < 3; ++i) parent[find(t)] = find(owner[{tris[t][(i + 1) % 3], tris[t][i]}]);
  std::map<int, std::vector<int>> components;
  for (int t = 0; t < nt; ++t) components[find(t)].push_back(t);
  for (const auto& [root, which] : components)
    if (volumeSign(x, tris, which) <= 0)
      fail(who + "the component of triangle " + std::to_string(root) + " has a signed volume <= 0");
  if (mesh.numVertices() != nv || mesh.numTriangles() != nt || mesh.numEdges() != static_cast<int>(directed.size()) / 2 ||
      mesh.numComponents() != static_cast<int>(components.size()))
    fail(who + "its counts (V " + std::to_string(mesh.numVertices()) + ", F " + std::to_string(mesh.numTriangles()) +
         ", E " + std::to_string(mesh.numEdges()) + ", components " + std::to_string(mesh.numComponents()) +
         ") are wrong (E " + std::to_string(directed.size() / 2) + ", components " +
         std::to_string(components.size()) + ")");
}

// fromMesh, then the verification; a null pointer when rejected.
std::unique_ptr<Mesh> build(const RawMesh& raw, const char* name) {
  std::unique_ptr<Mesh> mesh;
  try {
    mesh = std::make_unique<Mesh>(Mesh::fromMesh(raw.vertices, raw.triangles));
  } catch (const mink::InvalidInput& e) {
    if (raw.mustAccept) fail(std::string("fromMesh rejected ") + name + ", a valid " + raw.origin + ": " + e.what());
    return nullptr;
  } catch (const std::exception& e) {
    fail(std::string("fromMesh threw something other than InvalidInput: ") + e.what());
  }
  verifyMesh(*mesh, raw, name);
  return mesh;
}

// ---------------------------------------------------------------------------------------
// 2. update().

// Rigid (1), not rigid (-1), or within a factor 2 of mink's orthonormality threshold
// (defaults::kRotationTolerance = 1e-6), where either answer is right (0).
int poseVerdict(const mink::Pose<double>& p) {
  const double big = mink::ScalarTraits<double>::largestCoordinate();
  if (!p.rotation.allFinite() || !p.translation.allFinite()) return -1;
  if (p.translation.cwiseAbs().maxCoeff() > big) return -1;
  const Eigen::Matrix<LD, 3, 3> R = p.rotation.cast<LD>();
  const LD err = (R.transpose() * R - Eigen::Matrix<LD, 3, 3>::Identity()).cwiseAbs().maxCoeff();
  if (err > 2e-6L) return -1;
  if (R.determinant() < 0.5L) return -1;  // a reflection (near-orthonormal: det near ±1)
  return err < 0.5e-6L ? 1 : 0;
}

LD orthoError(const M3& R) {
  const Eigen::Matrix<LD, 3, 3> r = R.cast<LD>();
  return (r.transpose() * r - Eigen::Matrix<LD, 3, 3>::Identity()).cwiseAbs().maxCoeff();
}

// Distance from p to triangle abc (Ericson, Real-Time Collision Detection, 5.1.5); for a
// degenerate triangle the nearest of its sides.
LD segmentDistance(const VL& p, const VL& a, const VL& b) {
  const VL ab = b - a;
  const LD l2 = ab.squaredNorm();
  LD t = l2 > 0 ? (p - a).dot(ab) / l2 : 0;
  t = std::min<LD>(1, std::max<LD>(0, t));
  return (p - (a + t * ab)).norm();
}

LD triangleDistance(const VL& p, const VL& a, const VL& b, const VL& c) {
  const VL ab = b - a, ac = c - a, ap = p - a;
  const LD d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.norm();
  const VL bp = p - b;
  const LD d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.norm();
  const LD vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + d1 / (d1 - d3) * ab)).norm();
  const VL cp = p - c;
  const LD d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.norm();
  const LD vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + d2 / (d2 - d6) * ac)).norm();
  const LD va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
    return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).norm();
  const LD denom = va + vb + vc;
  LD d = (p - (a + ab * (vb / denom) + ac * (vc / denom))).norm();
  if (!std::isfinite(static_cast<double>(d)) || !(denom > 0))
    d = std::min({segmentDistance(p, a, b), segmentDistance(p, b, c), segmentDistance(p, c, a)});
  return d;
}

struct Summary {
  bool threw = false;
  std::string why;
  std::vector<std::array<int, 3>> facets;  // (type, featureA, featureB), sorted
  std::size_t triangles = 0;
  LD area = 0;
  LD slack = 0;        // the distance slack of the ball test
  bool skipped = false;  // not asked
};

std::string facetName(const std::array<int, 3>& f) {
  return "(" + std::to_string(f[0]) + "," + std::to_string(f[1]) + "," + std::to_string(f[2]) + ")";
}

// Distance from the centre to the convolution facet f (world frame, long double): FV
// the triangle of A minus a vertex of B, VF a vertex of A minus the triangle of B, EE the
// parallelogram of the two edges.
LD facetDistance(const Mesh& A, const Mesh& B, const mink::Pose<double>& pA, const mink::Pose<double>& pB,
                 const V& centre, const std::array<int, 3>& f) {
  using ML = Eigen::Matrix<LD, 3, 3>;
  const ML RA = pA.rotation.cast<LD>(), RB = pB.rotation.cast<LD>();
  const VL tA = pA.translation.cast<LD>(), tB = pB.translation.cast<LD>();
  auto m = [&](int i, int j) -> VL { return VL(RA * A.vertex(i).cast<LD>() + tA - RB * B.vertex(j).cast<LD>() - tB); };
  const VL c = centre.cast<LD>();
  switch (f[0]) {
    case 0: {
      const Tri& t = A.triangle(f[1]);
      return triangleDistance(c, m(t[0], f[2]), m(t[1], f[2]), m(t[2], f[2]));
    }
    case 1: {
      const Tri& t = B.triangle(f[2]);
      return triangleDistance(c, m(f[1], t[0]), m(f[1], t[1]), m(f[1], t[2]));
    }
    default: {
      const auto ea = A.edgeVertices(f[1]);
      const auto eb = B.edgeVertices(f[2]);
      const VL p00 = m(ea.first, eb.first), p10 = m(ea.second, eb.first), p11 = m(ea.second, eb.second),
               p01 = m(ea.first, eb.second);
      return std::min(triangleDistance(c, p00, p10, p11), triangleDistance(c, p00, p11, p01));
    }
  }
}

const char* methodName(mink::LocalSumMethod m) {
  switch (m) {
    case mink::LocalSumMethod::BruteForce: return "BruteForce";
    case mink::LocalSumMethod::SphereTree: return "SphereTree";
    case mink::LocalSumMethod::BoxTrees: return "BoxTrees";
    default: return "ConvexMaps";
  }
}


// Checks one returned patch on its own; returns its summary.
Summary checkPatch(const mink::LocalMinkowskiSum<double>& lms, const mink::MinkowskiPatch<double>& P,
                   const mink::Pose<double>& pA, const mink::Pose<double>& pB, const V& centre, double radius,
                   const char* method) {
  const std::string where = std::string(" (") + method + ")";
  Summary s;
  if (P.pairs.size() != P.triangles.size()) fail("patch: pairs and triangles differ in number" + where);
  const int nv = static_cast<int>(P.vertices.size());
  LD L = centre.cast<LD>().cwiseAbs().maxCoeff() + static_cast<LD>(radius);
  for (int v = 0; v < nv; ++v) {
    if (!P.vertices[v].allFinite()) fail("patch vertex " + std::to_string(v) + " is not finite" + where);
    L = std::max<LD>(L, P.vertices[v].cast<LD>().cwiseAbs().maxCoeff());
  }
  // The work is done in A's frame and rotated back by poseA: rounding of the scene, and
  // for a rotation e off orthonormal (e <= 1e-6 accepted), lengths off by up to e.
  const LD e = orthoError(pA.rotation) + orthoError(pB.rotation);
  // 2^-1040 absolute: constructed points of a scene in the denormal range round to
  // multiples of 2^-1074.
  const LD slack = static_cast<LD>(radius) * 1e-9L + (1e-13L + 4 * e) * L + std::ldexp(1.0L, -1040);
  const VL c = centre.cast<LD>();
  for (std::size_t t = 0; t < P.triangles.size(); ++t) {
    const Tri& tri = P.triangles[t];
    for (int k = 0; k < 3; ++k)
      if (tri[k] < 0 || tri[k] >= nv) fail("patch triangle " + std::to_string(t) + " has index out of range" + where);
    const VL a = P.vertices[tri[0]].cast<LD>(), b = P.vertices[tri[1]].cast<LD>(), d = P.vertices[tri[2]].cast<LD>();
    const LD dist = triangleDistance(c, a, b, d);
    if (dist > static_cast<LD>(radius) + slack) {
      char buf[200];
      std::snprintf(buf, sizeof buf, ": distance %.17Lg from the centre, radius %.17g", dist, radius);
      fail("patch triangle " + std::to_string(t) + " misses the ball" + where + buf);
    }
    s.area += (b - a).cross(d - a).norm() / 2;
  }
  s.triangles = P.triangles.size();
  s.slack = slack;
  for (const auto& f : lms.facets()) s.facets.push_back({static_cast<int>(f.type), f.featureA, f.featureB});
  std::sort(s.facets.begin(), s.facets.end());
  return s;
}

// 3. The CPD query on small scenes (|A| · |B| <= 400 triangle pairs, at most 8 balls):
//    ContinuousPenetrationDepth coherent over the two poses, and penetrationDepth().
void checkQueries(const Mesh& A, const Mesh& B, const mink::Pose<double> (&poses)[4]) {
  mink::CpdOptions<double> opt;
  opt.maxIterations = 8;
  mink::ContinuousPenetrationDepth<double> cpd(A, B, opt);
  for (int step = 0; step < 2; ++step) {
    gScene.step = step;
    const mink::Pose<double>& a = poses[2 * step];
    const mink::Pose<double>& b = poses[2 * step + 1];
    const int va = poseVerdict(a), vb = poseVerdict(b);
    for (int mode = 0; mode < 2; ++mode) {
      const char* who = mode == 0 ? "ContinuousPenetrationDepth::query" : "penetrationDepth";
      mink::CpdResult<double> r;
      bool threw = false;
      std::string why;
      try {
        r = mode == 0 ? cpd.query(a, b) : mink::penetrationDepth(A, a, B, b, opt);
      } catch (const mink::InvalidInput& e) {
        threw = true;
        why = e.what();
      } catch (const std::exception& e) {
        fail(std::string(who) + " threw something other than InvalidInput: " + e.what());
      }
      if (threw && va > 0 && vb > 0) fail(std::string(who) + " rejected rigid poses: " + why);
      if (!threw && (va < 0 || vb < 0)) fail(std::string(who) + " accepted a pose that is not rigid");
      if (gVerbose && !threw)
        std::fprintf(stderr, "%s %d: status %d depth %.17g point %.17g %.17g %.17g normal %.17g %.17g %.17g residual %.3g, %d balls\n",
                     who, step + 1, static_cast<int>(r.status), r.depth, r.point.x(), r.point.y(), r.point.z(), r.normal.x(),
                     r.normal.y(), r.normal.z(), r.residual, r.iterations);
      if (threw) continue;
      bool overlap = true;
      try {
        overlap = mink::MeshOverlap<double>(A, a, B, b).overlaps();
      } catch (const mink::InvalidInput&) {
        continue;  // a pose in the band where either verdict is allowed
      }
      if (r.status == mink::CpdStatus::Separated) {
        if (r.depth != 0) fail(std::string(who) + ": Separated with a non-zero depth");
        continue;
      }
      if (!overlap) fail(std::string(who) + " reports an overlap of meshes that share no point");
      if (!std::isfinite(r.depth) || !(r.depth > 0) || !r.point.allFinite() || !r.normal.allFinite())
        fail(std::string(who) + ": an overlap answered with a zero or non-finite depth, point or normal");
      if (std::fabs(r.direction.norm() - 1) > 1e-9) fail(std::string(who) + ": the direction is not unit");
      if ((r.point - r.depth * r.direction).norm() > 1e-9 * r.depth)
        fail(std::string(who) + ": point is not depth * direction");
      // Definition 1 holds to the rounding of the scene, not of the depth: two boxes at
      // 2^200 overlapping by 1e28 (below their coordinates' rounding, 1e44) have a depth
      // that is all rounding.
      double L = 0;
      for (const Mesh* X : {&A, &B})
        for (const V& v : X->vertices()) L = std::max(L, v.cwiseAbs().maxCoeff());
      L += std::max(a.translation.cwiseAbs().maxCoeff(), b.translation.cwiseAbs().maxCoeff());
      const double e = static_cast<double>(orthoError(a.rotation) + orthoError(b.rotation));
      if (mode == 0 && r.status == mink::CpdStatus::Penetrating &&
          r.normal.cross(r.point).norm() > 1e-6 * r.depth + (1e-12 + 4 * e) * L)
        fail("ContinuousPenetrationDepth::query: Penetrating, but the normal at q misses the origin");
    }
  }
}

void checkUpdates(const Mesh& A, const Mesh& B, Decoder& in, int unitExp) {
  const mink::Pose<double> pA = decodePose(in, unitExp, false), pB = decodePose(in, unitExp, true);
  const mink::Pose<double> pA2 = moved(pA, in, unitExp), pB2 = moved(pB, in, unitExp);
  // The ball: centre near tA − tB (where M is) or on the lattice, or special; radius in
  // units of A's scale, or special.
  V centre;
  const int ck = in.u8() % 4;
  if (ck == 0) {
    centre = pA.translation - pB.translation + vector3(in, 0, unitExp - 1);
  } else if (ck == 1) {
    centre = vector3(in, 0, unitExp);
  } else if (ck == 2) {
    centre = vector3(in, 4, unitExp);
  } else {
    centre = vector3(in, 3, unitExp);
  }
  double radius;
  const int rk = in.u8() % 8;
  static const double units[8] = {0.25, 0.5, 1, 1.5, 2, 3, 5, 20};
  if (rk < 4) {
    radius = std::ldexp(units[in.u8() % 8], unitExp);
  } else if (rk == 4) {
    radius = in.special();
  } else if (rk == 5) {
    radius = -std::ldexp(1.0, unitExp);
  } else if (rk == 6) {
    radius = in.f64();
  } else {
    radius = std::ldexp(1.0 + in.i8() / 128.0, unitExp);
  }
  gScene.poses[0] = pA;
  gScene.poses[1] = pB;
  gScene.poses[2] = pA2;
  gScene.poses[3] = pB2;
  gScene.centre = centre;
  gScene.radius = radius;
  const bool argsOk = centre.allFinite() && radius > 0 && std::isfinite(radius);

  std::vector<mink::LocalSumMethod> methods{mink::LocalSumMethod::SphereTree, mink::LocalSumMethod::BoxTrees,
                                            mink::LocalSumMethod::ConvexMaps};
  if (A.numTriangles() <= 40 && B.numTriangles() <= 40) methods.insert(methods.begin(), mink::LocalSumMethod::BruteForce);
  std::vector<std::unique_ptr<mink::LocalMinkowskiSum<double>>> sums;
  for (auto m : methods) {
    mink::LocalMinkowskiSumOptions<double> opt;
    opt.method = m;
    try {
      sums.push_back(std::make_unique<mink::LocalMinkowskiSum<double>>(A, B, opt));
    } catch (const std::exception& e) {
      fail(std::string("the LocalMinkowskiSum constructor threw: ") + e.what());
    }
  }
  for (int step = 0; step < 2; ++step) {
    gScene.step = step;
    const mink::Pose<double>& a = step == 0 ? pA : pA2;
    const mink::Pose<double>& b = step == 0 ? pB : pB2;
    const int va = poseVerdict(a), vb = poseVerdict(b);
    const bool mustThrow = !argsOk || va < 0 || vb < 0;
    const bool mustNotThrow = argsOk && va > 0 && vb > 0;
    std::vector<Summary> out;
    for (std::size_t k = 0; k < methods.size(); ++k) {
      Summary s;
      // The second update is there for ConvexMaps' coherent walk; SphereTree, which
      // rebuilds every call, is asked once (a fifth of the time saved).
      if (step == 1 && methods[k] == mink::LocalSumMethod::SphereTree) {
        s.skipped = true;
        out.push_back(std::move(s));
        continue;
      }
      const mink::MinkowskiPatch<double>* P = nullptr;
      const auto t0 = std::chrono::steady_clock::now();
      try {
        P = &sums[k]->update(a, b, centre, radius);
      } catch (const mink::InvalidInput& e) {
        s.threw = true;
        s.why = e.what();
      } catch (const std::exception& e) {
        fail(std::string("update threw something other than InvalidInput (") + methodName(methods[k]) + "): " + e.what());
      }
      if (s.threw && mustNotThrow) fail(std::string("update rejected valid arguments: ") + s.why);
      if (!s.threw && mustThrow)
        fail(std::string("update accepted a non-finite centre, a bad radius or a pose that is not rigid (") +
             methodName(methods[k]) + ")");
      if (!s.threw && P) s = checkPatch(*sums[k], *P, a, b, centre, radius, methodName(methods[k]));
      if (gVerbose) {
        if (k == 0 && step == 0) printScene();
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        std::fprintf(stderr, "update %d %s: %s, %zu facets, %zu triangles, area %.17Lg, %.1f ms\n", step + 1,
                     methodName(methods[k]), s.threw ? s.why.c_str() : "patch", s.facets.size(), s.triangles, s.area, ms);
      }
      out.push_back(std::move(s));
    }
    // out[0] is the reference: BruteForce (every feature pair) when it ran, else
    // ConvexMaps. ConvexMaps and BoxTrees must gather exactly what BruteForce does (all
    // complete, all filter by the same facet box test); SphereTree culls with tighter
    // spheres, so it may drop facets whose box meets the region box, but only ones that
    // miss the ball.
    const std::size_t ref = methods[0] == mink::LocalSumMethod::BruteForce ? 0 : methods.size() - 1;
    for (std::size_t k = 0; k < out.size(); ++k) {
      if (k == ref || out[k].skipped) continue;
      const std::string pair = std::string(methodName(methods[k])) + " vs " + methodName(methods[ref]);
      if (out[k].threw != out[ref].threw) fail("one method threw and another did not: " + pair);
      if (out[k].threw) continue;
      const auto& x = out[k].facets;
      const auto& y = out[ref].facets;
      const bool mayCull = methods[k] == mink::LocalSumMethod::SphereTree;
      std::string diff;
      for (const auto& f : x)
        if (!std::binary_search(y.begin(), y.end(), f)) diff += " extra " + facetName(f);
      for (const auto& f : y)
        if (!std::binary_search(x.begin(), x.end(), f)) {
          if (!mayCull) {
            diff += " missing " + facetName(f);
          } else {
            const LD dist = facetDistance(A, B, a, b, centre, f);
            if (!(dist > static_cast<LD>(radius) + out[ref].slack))
              diff += " missing " + facetName(f) + " at distance " + std::to_string(static_cast<double>(dist));
          }
        }
      if (!diff.empty())
        fail("methods gather different convolution facets (type FV=0 VF=1 EE=2, featureA, featureB), " + pair + ":" +
             diff.substr(0, 600));
      if (x != y) continue;  // a different subdivision: the triangles may differ
      if (out[k].triangles != out[ref].triangles)
        fail("methods return different numbers of triangles: " + pair + ": " + std::to_string(out[k].triangles) +
             " vs " + std::to_string(out[ref].triangles));
      const LD a1 = out[k].area, a0 = out[ref].area;
      if (std::fabs(a1 - a0) > 1e-9L * std::max(a1, a0)) {
        char buf[160];
        std::snprintf(buf, sizeof buf, ": %.17Lg vs %.17Lg", a1, a0);
        fail("methods return different areas: " + pair + buf);
      }
    }
  }
  if (A.numTriangles() * B.numTriangles() <= 400) {
    const mink::Pose<double> poses[4] = {pA, pB, pA2, pB2};
    checkQueries(A, B, poses);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Decoder in(data, size);
  gScene = Scene();
  int unitA = 0, unitB = 0;
  const RawMesh rawA = decodeMesh(in, unitA);
  gScene.raw[0] = &rawA;
  const int bk = in.u8() % 4;
  RawMesh rawB;
  if (bk == 0 || bk == 1) {
    rawB = bk == 0 ? box() : octahedron();
    for (V& v : rawB.vertices) v = v.unaryExpr([&](double c) { return std::ldexp(c, unitA); });
    rawB.mustAccept = unitA >= -1000 && unitA <= 280;
    gScene.bKind = bk == 0 ? "a box at A's scale" : "an octahedron at A's scale";
  } else if (bk == 2) {
    rawB = decodeMesh(in, unitB);
    gScene.bKind = "decoded";
  } else {
    gScene.bKind = "A";
  }
  std::unique_ptr<Mesh> A = build(rawA, "A");
  std::unique_ptr<Mesh> B;
  if (bk != 3) {
    gScene.raw[1] = &rawB;
    B = build(rawB, "B");
  }
  if (!A) return 0;
  const Mesh& meshB = bk == 3 ? *A : B ? *B : *A;
  if (bk != 3 && !B) gScene.bKind = "A (B was rejected)";
  gScene.raw[1] = bk == 3 || !B ? &rawA : &rawB;
  // The mesh layer assumes surfaces that do not intersect themselves (fromMesh does not
  // check it); update() is only asked for such meshes.
  if (mink::findSelfIntersection(*A).found) return 0;
  if (&meshB != A.get() && mink::findSelfIntersection(meshB).found) return 0;
  try {
    checkUpdates(*A, meshB, in, unitA);
  } catch (const std::exception& e) {
    fail(std::string("the harness caught an exception: ") + e.what());
  }
  return 0;
}
