// mink/polyhedron/detail/quickhull.hpp — the triangulated convex hull of a point set.
//
// Quickhull: C. B. Barber, D. P. Dobkin, H. Huhdanpaa, "The Quickhull Algorithm for
// Convex Hulls", ACM TOMS 22(4), 1996.
//   1. Start from a tetrahedron of extreme points (lexicographic minimum, the point
//      farthest from it, the point farthest from their line, from their plane).
//   2. Give every point to one face it lies strictly above (its outside set, a list
//      threaded through one array: no allocation per face).
//   3. Take a face with points; its farthest point is the eye. Faces the eye is above
//      form a disc (the visible set); its boundary is the horizon.
//   4. Replace the visible faces by a cone of triangles from the eye to the horizon;
//      hand the visible faces' points to the new faces (or drop them: inside).
//   5. Repeat until no face has points. The triangles come out in Morton order (see
//      collect()).
// "p is above face (a, b, c)" is decided exactly: for floating-point T the sign of
// orient3d (core/orientation.hpp), through a per-face filter for double (above()), the
// exact sign of n.(p - a) for exact T. So the triangulation is the
// exact hull of the given numbers and always consistent (a tolerance here instead breaks
// quickhull on nearly coplanar input: faces end up facing the wrong way). `tol` only
// rejects (nearly) degenerate input when choosing the first tetrahedron. The result may
// contain coplanar neighbouring triangles and non-corner vertices: the polyhedron builder
// merges them, within the tolerance.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <type_traits>
#include <string>
#include <vector>

#include "mink/core/error.hpp"
#include "mink/core/detail/spatial_order.hpp"
#include "mink/core/orientation.hpp"
#include "mink/core/scalar_traits.hpp"
#include "mink/core/types.hpp"

namespace mink {
namespace detail {

template <class T>
class Quickhull {
 public:
  /// Triangles (indices into `points`, counter-clockwise seen from outside) in `tris`, or
  /// the Error "all points coincide / are collinear / are coplanar" (then `tris` is empty).
  [[nodiscard]] static Error run(const std::vector<Vec3<T>>& points, const T& tol,
                                 std::vector<std::array<int, 3>>& tris) {
    tris.clear();
    Quickhull q(points, tol);
    if (Error e = q.buildSimplex()) return e;
    q.expand();
    tris = q.collect();
    return Error();
  }

 private:
  struct Face {
    std::array<int, 3> v;    // corners, CCW from outside
    std::array<int, 3> nbr;  // face across edge v[i] -> v[i+1]
    Vec3<T> n;               // (v1 − v0) × (v2 − v0): exact for exact T, rounded otherwise
    Vec3<T> perm;            // double: the error bound's factors (see above())
    int head = -1;           // first point of the outside set (a list through next_)
    int eye = -1;            // farthest outside point
    T eyeDist = T(0);        // its n . (p − v0): proportional to its distance
    bool alive = true;
    int visitMark = -1;
  };

  Quickhull(const std::vector<Vec3<T>>& p, const T& tol) : pts_(p), tol_(tol), next_(p.size(), -1) {
    faces_.reserve(4 * p.size() + 8);
  }

  /// Is point i strictly above face f? `height` gets n . (p_i − v0), an increasing function
  /// of the distance for ranking the points of one face (rounded for inexact T).
  /// Decided exactly: for double, n . (p_i − v0) is the orientation determinant
  /// det[v1 − v0, v2 − v0, p_i − v0] expanded along its last row, with the face's minors
  /// (n) and their absolute products (perm) computed once per face; Shewchuk's forward
  /// error bound for that evaluation (his o3derrboundA, taken with a margin: 8 + 64 eps
  /// instead of 7 + 56 eps, for the different grouping of the permanent) plus the
  /// denormal term of orient3d decides almost every case, and orient3d, which is exact,
  /// the rest.
  bool above(const Face& f, int i, T& height) const {
    const Vec3<T>& a = pts_[f.v[0]];
    const Vec3<T> w = pts_[i] - a;
    height = f.n.dot(w);
    if constexpr (ScalarTraits<T>::isExact) {
      return height > T(0);
    } else if constexpr (std::is_same<T, double>::value) {
      using std::abs;
      const T aw0 = abs(w[0]), aw1 = abs(w[1]), aw2 = abs(w[2]);
      const T perm = aw0 * f.perm[0] + aw1 * f.perm[1] + aw2 * f.perm[2];
      constexpr T eps = std::numeric_limits<T>::epsilon() / T(2);
      const T bound = (T(8) + T(64) * eps) * eps * perm + denormalErrorBound(T(2) * (aw0 + aw1 + aw2) + T(4));
      if (height > bound) return true;
      if (-height > bound) return false;
      return orient3d(a, pts_[f.v[1]], pts_[f.v[2]], pts_[i]) > 0;
    } else {
      return orient3d(a, pts_[f.v[1]], pts_[f.v[2]], pts_[i]) > 0;
    }
  }

  int makeFace(int a, int b, int c) {
    const int fi = static_cast<int>(faces_.size());
    faces_.emplace_back();
    Face& f = faces_[fi];
    f.v = {a, b, c};
    f.nbr = {-1, -1, -1};
    const Vec3<T> u = pts_[b] - pts_[a], v = pts_[c] - pts_[a];
    f.n = Vec3<T>(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]);
    if constexpr (!ScalarTraits<T>::isExact) {
      using std::abs;
      f.perm = Vec3<T>(abs(u[1] * v[2]) + abs(u[2] * v[1]), abs(u[2] * v[0]) + abs(u[0] * v[2]),
                       abs(u[0] * v[1]) + abs(u[1] * v[0]));
    }
    f.head = -1;
    f.eye = -1;
    f.eyeDist = T(0);
    f.alive = true;
    f.visitMark = -1;
    return fi;
  }

  void addOutside(int fi, int p, const T& d) {
    Face& f = faces_[fi];
    next_[p] = f.head;
    f.head = p;
    if (f.eye < 0 || d > f.eyeDist) {
      f.eye = p;
      f.eyeDist = d;
    }
  }

  // Hands point p to the first of `candidates` it is strictly above; false if none.
  template <class Faces>
  bool assign(int p, const Faces& candidates) {
    T d;
    for (int fi : candidates) {
      if (above(faces_[fi], p, d)) {
        addOutside(fi, p, d);
        return true;
      }
    }
    return false;
  }

  [[nodiscard]] Error buildSimplex() {
    const int n = static_cast<int>(pts_.size());
    // Lexicographic minimum: always a corner of the hull.
    int i0 = 0;
    for (int i = 1; i < n; ++i) {
      const auto& a = pts_[i];
      const auto& b = pts_[i0];
      if (a.x() < b.x() || (a.x() == b.x() && (a.y() < b.y() || (a.y() == b.y() && a.z() < b.z()))))
        i0 = i;
    }
    // The degeneracy tests below are polynomials of degree up to 6 in the coordinates:
    // evaluate them on differences scaled by a power of two (exact) to unit order, so
    // that large or small shapes neither overflow nor underflow.
    int e = 0;
    if constexpr (!ScalarTraits<T>::isExact) {
      T m = T(0);
      for (int i = 0; i < n; ++i) m = std::max(m, (pts_[i] - pts_[i0]).cwiseAbs().maxCoeff());
      if (m > T(0)) e = std::ilogb(m);
    }
    auto diff = [&](int i, int j) {
      Vec3<T> d = pts_[i] - pts_[j];
      if constexpr (!ScalarTraits<T>::isExact)
        for (int k = 0; k < 3; ++k) d[k] = std::ldexp(d[k], -e);
      return d;
    };
    T tolS = tol_;
    if constexpr (!ScalarTraits<T>::isExact) tolS = std::ldexp(tol_, -e);
    // Farthest from it: the maximum of a strictly convex function is a corner.
    int i1 = i0;
    T best = T(0);
    for (int i = 0; i < n; ++i) {
      const T d = diff(i, i0).squaredNorm();
      if (d > best) {
        best = d;
        i1 = i;
      }
    }
    if (!(best > tolS * tolS)) return Error("fromPoints: all points coincide (within the tolerance)");
    const Vec3<T> dir = diff(i1, i0);
    int i2 = i0;
    best = T(0);
    for (int i = 0; i < n; ++i) {
      const T d = diff(i, i0).cross(dir).squaredNorm();
      if (d > best) {
        best = d;
        i2 = i;
      }
    }
    // distance^2 to the line is d / |dir|^2
    if (!(best > tolS * tolS * dir.squaredNorm()))
      return Error("fromPoints: all points are collinear (within the tolerance)");
    const Vec3<T> nrm = dir.cross(diff(i2, i0));
    int i3 = i0;
    best = T(0);
    T bestSigned = T(0);
    for (int i = 0; i < n; ++i) {
      const T s = nrm.dot(diff(i, i0));
      const T d = absValue(s);
      if (d > best) {
        best = d;
        bestSigned = s;
        i3 = i;
      }
    }
    if (!(best * best > tolS * tolS * nrm.squaredNorm()))
      return Error("fromPoints: all points are coplanar (within the tolerance)");
    (void)bestSigned;
    // Orient so that i3 lies below the plane of (i0, i1, i2). Decided exactly: every later
    // step trusts this orientation, and the rounded products above can give a sliver
    // simplex (input within rounding of a plane, accepted with tolerance 0: 1e-185 wide,
    // 1e-294 thick) the wrong sign, and the hull came out inside out.
    int o = 0;
    if (Error e = exactSimplex(i0, i1, i2, i3, o)) return e;
    if (o > 0) std::swap(i1, i2);
    const int f0 = makeFace(i0, i1, i2);
    const int f1 = makeFace(i0, i3, i1);
    const int f2 = makeFace(i1, i3, i2);
    const int f3 = makeFace(i2, i3, i0);
    link(f0, 0, f1, 2);  // i0->i1 / i1->i0
    link(f0, 1, f2, 2);  // i1->i2 / i2->i1
    link(f0, 2, f3, 2);  // i2->i0 / i0->i2
    link(f1, 0, f3, 1);  // i0->i3 / i3->i0
    link(f1, 1, f2, 0);  // i3->i1 / i1->i3
    link(f2, 1, f3, 0);  // i3->i2 / i2->i3
    std::vector<int> all = {f0, f1, f2, f3};
    for (int i = 0; i < n; ++i) {
      if (i == i0 || i == i1 || i == i2 || i == i3) continue;
      assign(i, all);
    }
    return Error();
  }

  /// orient3d(i0, i1, i2, i3), after replacing i2 or i3 where the rounded choices above
  /// made a simplex that is exactly degenerate: i2 exactly on the line i0 i1, or i3 exactly
  /// in the plane i0 i1 i2 (each replacement an O(n) scan, only for such input), in `o`.
  /// The Error when every point is exactly collinear or coplanar with them.
  [[nodiscard]] Error exactSimplex(int i0, int i1, int& i2, int& i3, int& o) const {
    const int n = static_cast<int>(pts_.size());
    if (collinear(i0, i1, i2)) {
      int j = 0;
      while (j < n && collinear(i0, i1, j)) ++j;
      if (j == n) return Error("fromPoints: all points are collinear");
      i2 = j;
    }
    o = orient3d(pts_[i0], pts_[i1], pts_[i2], pts_[i3]);
    for (int j = 0; o == 0 && j < n; ++j) {
      o = orient3d(pts_[i0], pts_[i1], pts_[i2], pts_[j]);
      if (o != 0) i3 = j;
    }
    if (o == 0) return Error("fromPoints: all points are coplanar");
    return Error();
  }

  /// Are points a, b, c exactly collinear? Iff their projections on the three coordinate
  /// planes are; each projection's orientation is the exact orient3d of the projected
  /// points with a unit point off the plane (whose coordinates 0 and 1 keep it exact).
  bool collinear(int a, int b, int c) const {
    for (int axis = 0; axis < 3; ++axis) {
      auto lift = [&](int i) {
        Vec3<T> x = pts_[i];
        x[axis] = T(0);
        return x;
      };
      Vec3<T> up = Vec3<T>::Zero();
      up[axis] = T(1);
      if (orient3d(lift(a), lift(b), lift(c), up) != 0) return false;
    }
    return true;
  }

  void link(int fa, int ea, int fb, int eb) {
    faces_[fa].nbr[ea] = fb;
    faces_[fb].nbr[eb] = fa;
  }

  void expand() {
    std::vector<int> visible, newFaces;
    struct Horizon {
      int a, b, outsideFace, outsideEdge;
    };
    std::vector<Horizon> horizon;
    int mark = 0;
    // Faces in creation order (each new face is appended): the order fixes how coplanar
    // points are triangulated, hence which triangle seeds a merged face and the rounding of
    // its normal, which the MDD stress tests' bounds were measured with.
    for (int fi = 0; fi < static_cast<int>(faces_.size()); ++fi) {
     while (faces_[fi].alive && faces_[fi].head >= 0) {
      const int eye = faces_[fi].eye;
      ++mark;
      // Visible set and horizon by depth-first search; recording the horizon edges
      // in the order the search meets them around the disc gives a closed loop.
      visible.clear();
      horizon.clear();
      visitHorizon(fi, eye, mark, visible, horizon);
      const int h = static_cast<int>(horizon.size());
      bool loopOk = h >= 3;
      for (int k = 0; k < h && loopOk; ++k) loopOk = horizon[k].b == horizon[(k + 1) % h].a;
      if (!loopOk) {
        // Only reachable through rounding with inexact T: the visible set is not a
        // disc. Treat the eye as inside (it is within rounding of the hull).
        for (int vf : visible) faces_[vf].visitMark = -1;
        unlink(fi, eye);
        refreshEye(fi);
        continue;
      }
      // Cone of new faces.
      newFaces.clear();
      for (int k = 0; k < h; ++k) {
        const int nf = makeFace(horizon[k].a, horizon[k].b, eye);
        faces_[nf].nbr[0] = horizon[k].outsideFace;
        faces_[horizon[k].outsideFace].nbr[horizon[k].outsideEdge] = nf;
        newFaces.push_back(nf);
      }
      for (int k = 0; k < h; ++k) {
        // edge 1 is b -> eye, shared with the next face's edge 2 (eye -> a).
        link(newFaces[k], 1, newFaces[(k + 1) % h], 2);
      }
      for (int vf : visible) {
        int p = faces_[vf].head;
        faces_[vf].alive = false;
        faces_[vf].head = -1;
        while (p >= 0) {
          const int after = next_[p];
          if (p != eye) assign(p, newFaces);
          p = after;
        }
      }
     }
    }
  }

  /// Removes point p from face fi's outside set.
  void unlink(int fi, int p) {
    Face& f = faces_[fi];
    if (f.head == p) {
      f.head = next_[p];
      return;
    }
    for (int q = f.head; q >= 0; q = next_[q])
      if (next_[q] == p) {
        next_[q] = next_[p];
        return;
      }
  }

  void refreshEye(int fi) {
    Face& f = faces_[fi];
    f.eye = -1;
    for (int p = f.head; p >= 0; p = next_[p]) {
      const T d = f.n.dot(pts_[p] - pts_[f.v[0]]);
      if (f.eye < 0 || d > f.eyeDist) {
        f.eye = p;
        f.eyeDist = d;
      }
    }
  }

  // Depth-first search over the faces visible from `eye`. Each face entered through
  // an edge examines its other edges in rotational order after that edge, so the
  // horizon edges are emitted as one closed counter-clockwise loop.
  template <class HorizonVec>
  void visitHorizon(int start, int eye, int mark, std::vector<int>& visible, HorizonVec& horizon) {
    std::vector<DfsFrame>& stack = dfs_;
    stack.clear();
    faces_[start].visitMark = mark;
    visible.push_back(start);
    stack.push_back({start, 0, 0, 3});
    while (!stack.empty()) {
      DfsFrame& fr = stack.back();
      if (fr.count == fr.limit) {
        stack.pop_back();
        continue;
      }
      const int e = (fr.first + fr.count) % 3;
      ++fr.count;
      const int cur = fr.face;
      const int nb = faces_[cur].nbr[e];
      Face& nf = faces_[nb];
      if (nf.visitMark == mark) continue;
      int back = 0;
      while (nf.nbr[back] != cur) ++back;
      T height;
      if (above(nf, eye, height)) {
        nf.visitMark = mark;
        visible.push_back(nb);
        stack.push_back({nb, (back + 1) % 3, 0, 2});
      } else {
        const Face& cf = faces_[cur];
        horizon.push_back({cf.v[e], cf.v[(e + 1) % 3], nb, back});
      }
    }
  }

  /// The live triangles in Morton (Z-) order of their first corner: every later pass over
  /// the hull (vertex numbering by first use, twins, rings, face planes) then touches
  /// memory that neighbours on the surface share, where face-slot order scatters it (at
  /// 100k points the builder's passes were bound by cache misses).
  std::vector<std::array<int, 3>> collect() const {
    std::vector<int> alive;
    std::vector<Vec3<T>> firsts;
    for (int fi = 0; fi < static_cast<int>(faces_.size()); ++fi)
      if (faces_[fi].alive) {
        alive.push_back(fi);
        firsts.push_back(pts_[faces_[fi].v[0]]);
      }
    // The Morton box also spans the first corner of the first face (the lexicographic
    // minimum, a hull vertex), alive or not: the order this builder has always produced,
    // which the rounding of answers on small shapes follows. Its key is not output.
    const int extra = static_cast<int>(firsts.size());
    firsts.push_back(pts_[faces_[0].v[0]]);
    std::vector<std::array<int, 3>> out;
    out.reserve(alive.size());
    for (int i : mortonOrder(firsts))
      if (i != extra) out.push_back(faces_[alive[i]].v);
    return out;
  }

  const std::vector<Vec3<T>>& pts_;
  T tol_;
  std::vector<Face> faces_;
  std::vector<int> next_;       // per point: the next point of the same outside set, or -1
  struct DfsFrame {
    int face, first, count, limit;
  };
  std::vector<DfsFrame> dfs_;
};

}  // namespace detail
}  // namespace mink
