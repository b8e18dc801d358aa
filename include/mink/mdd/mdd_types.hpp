// mink/mdd/mdd_types.hpp — the result, options and cache of a minimum-directional-distance
// query (MDD-DUAL: Choi, Li, Rong, Wang, Cameron, "Computing the Minimum Directional
// Distance between Two Convex Polyhedra").
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>
#include <vector>

#include "mink/core/scalar_traits.hpp"
#include "mink/core/types.hpp"
#include "mink/mdd/detail/difference_polygon.hpp"
#include "mink/mdd/detail/region_crossings.hpp"

namespace mink {

/// Where the origin lies relative to M = P ⊕ −Q on the line of s (eq. (1) of Choi et al.).
enum class MddStatus {
  Separated,    ///< P and Q apart; moving Q by translation along s/|s| makes them touch
  Touching,     ///< P and Q touch (0 on the boundary of M; within tolerance for inexact T)
  Penetrating,  ///< P and Q overlap; translation is the shorter way out along ±s
  NoContact,    ///< no motion of Q along s ever makes P and Q touch (line misses M)
  IterationLimit,  ///< a search hit its iteration cap, or needed a fallback over more edge
                   ///< pairs than MddOptions::maxExhaustivePairs: no answer (distance,
                   ///< translation and parameter are NaN for floating-point T)
  InvalidInput  ///< builds without exceptions only (-fno-exceptions), where mdd() cannot
                ///< throw: the input is one that mdd() throws InvalidInput for (checkMddInput
                ///< gives the message); no answer (NaN as for IterationLimit)
};

/// Which step of mdd() answered (MddResult::path), from the cheapest: each exit of M along
/// the line (two for a penetrating query) is found by one of them, and the result names
/// the costliest that ran.
enum class MddPath {
  None,         ///< NoContact from the centre of duality, IterationLimit or InvalidInput
  Cache,        ///< the faces kept in the MddCache, certified again (fromCache)
  Certificate,  ///< a face at the exit-portal estimate's (or a kept face's) support
                ///< vertices whose facet the line crosses, accepted without a search
  Search,       ///< SEARCH-FV, SEARCH-VF, SEARCH-EE (faceType says which kind of face),
                ///< their answer accepted by the facet check
  Exhaustive,   ///< every FV, VF and EE face examined (usedFallback)
  Chord,        ///< the line clipped by every face plane of M (usedFallback)
  Grazing       ///< the line in a supporting plane of M: read off that facet (case 2)
};

/// Type of the face of M that the line of s hits (MDD paper section II-C).
enum class MddFaceType {
  None,  ///< NoContact, IterationLimit or InvalidInput
  FV,    ///< face of P (featureP) translated by a vertex of −Q (featureQ)
  VF,    ///< vertex of P (featureP) plus a face of −Q (featureQ)
  EE,    ///< parallelogram of an edge of P (featureP) and an edge of −Q (featureQ)
  Grazing  ///< the line only touches the boundary of M (case 2 of section IV-A):
           ///< featureP / featureQ are vertices of P and Q supporting that contact
};

/// The enumerator's name, as spelled in the code ("Separated", "Search", "EE", ...), for
/// logs and messages; "?" for a value outside the enumeration.
constexpr const char* toString(MddStatus s) noexcept {
  switch (s) {
    case MddStatus::Separated: return "Separated";
    case MddStatus::Touching: return "Touching";
    case MddStatus::Penetrating: return "Penetrating";
    case MddStatus::NoContact: return "NoContact";
    case MddStatus::IterationLimit: return "IterationLimit";
    case MddStatus::InvalidInput: return "InvalidInput";
  }
  return "?";
}

/// \copydoc toString(MddStatus)
constexpr const char* toString(MddPath p) noexcept {
  switch (p) {
    case MddPath::None: return "None";
    case MddPath::Cache: return "Cache";
    case MddPath::Certificate: return "Certificate";
    case MddPath::Search: return "Search";
    case MddPath::Exhaustive: return "Exhaustive";
    case MddPath::Chord: return "Chord";
    case MddPath::Grazing: return "Grazing";
  }
  return "?";
}

/// \copydoc toString(MddStatus)
constexpr const char* toString(MddFaceType t) noexcept {
  switch (t) {
    case MddFaceType::None: return "None";
    case MddFaceType::FV: return "FV";
    case MddFaceType::VF: return "VF";
    case MddFaceType::EE: return "EE";
    case MddFaceType::Grazing: return "Grazing";
  }
  return "?";
}

/// What a feature id of a polyhedron names (MddResult::featureOfP / featureOfQ).
enum class FeatureKind {
  None,    ///< no feature (index -1)
  Vertex,  ///< index: a vertex of the shape (ConvexPolyhedron::vertex)
  Edge,    ///< index: an edge of the shape (ConvexPolyhedron::edgeVertices)
  Face     ///< index: a face of the shape (ConvexPolyhedron::faceVertices)
};

/// A feature of P or Q: its kind and its index among the shape's features of that kind.
struct Feature {
  FeatureKind kind = FeatureKind::None;
  int index = -1;
  friend constexpr bool operator==(const Feature& a, const Feature& b) noexcept {
    return a.kind == b.kind && a.index == b.index;
  }
  friend constexpr bool operator!=(const Feature& a, const Feature& b) noexcept { return !(a == b); }
};

constexpr const char* toString(FeatureKind k) noexcept {
  switch (k) {
    case FeatureKind::None: return "None";
    case FeatureKind::Vertex: return "Vertex";
    case FeatureKind::Edge: return "Edge";
    case FeatureKind::Face: return "Face";
  }
  return "?";
}

namespace detail {
/// The kinds that featureP / featureQ name for a face type of M (MddFaceType's comments);
/// None: vertices when an id is set (NoContact's separating normal), else no feature.
constexpr Feature typedFeature(MddFaceType type, bool ofP, int index) noexcept {
  if (index < 0) return Feature{};
  switch (type) {
    case MddFaceType::FV: return Feature{ofP ? FeatureKind::Face : FeatureKind::Vertex, index};
    case MddFaceType::VF: return Feature{ofP ? FeatureKind::Vertex : FeatureKind::Face, index};
    case MddFaceType::EE: return Feature{FeatureKind::Edge, index};
    case MddFaceType::Grazing:
    case MddFaceType::None: return Feature{FeatureKind::Vertex, index};
  }
  return Feature{};
}
}  // namespace detail

/// Options of mdd() and intersects(). Defaults are in core/defaults.hpp.
template <class T>
struct MddOptions {
  /// |translation| (length units) at or below which the result is reported Touching.
  /// Negative: automatic, defaults::kMddTouchToleranceFactor * eps * (extent(P) +
  /// extent(Q) + |relative translation|) for inexact T; always 0 for exact T.
  T touchTolerance = T(-1);
  /// Cap on the candidate faces of M one search (one direction, all three phases)
  /// evaluates; negative: automatic, defaults::kMddVisitFactor * (faces(P) + faces(Q) +
  /// 64). Reaching it yields MddStatus::IterationLimit.
  long long maxVisits = -1;
  /// Cap on edges(P) * edges(Q) for the fallbacks that visit every face of M (quadratic
  /// in the sizes), used when a search cannot answer; negative: automatic,
  /// defaults::kMddExhaustivePairs. Above it such a query reports
  /// MddStatus::IterationLimit instead of running for seconds or minutes.
  long long maxExhaustivePairs = -1;
  /// Use Dobkin–Kirkpatrick hierarchies for cold support queries on large shapes.
  bool useHierarchy = true;
};

/// Result of mdd(). Frames: world (the frame of the poses and of s).
template <class T>
struct MddResult {
  MddStatus status = MddStatus::NoContact;
  /// Signed MDD in length units: > 0 separated, < 0 penetrating, 0 touching.
  /// NoContact: +infinity where T has one; IterationLimit: NaN where T has one. A type
  /// with neither (an exact rational) leaves distance, translation and parameter 0 in
  /// both cases: read `status` first.
  T distance = T(0);
  /// Signed, length units, along s/|s|: moving Q by translation * s/|s| brings P and Q
  /// into touching contact and |translation| is minimal. For exact T (no sqrt), this is
  /// parameter * |s| only when |s| == 1; use `parameter` for exact answers.
  T translation = T(0);
  /// The same motion as a multiple of s as given: moving Q by parameter * s. Exact for
  /// exact T (a ratio of polynomials in the inputs). For inexact T it is ±infinity when
  /// |translation| / |s| exceeds the type's range (a tiny s, e.g. |s| = 1e-300), and 0 or
  /// a denormal (its precision lost) when |translation| / |s| is below the type's normal
  /// range (a huge s against tiny shapes, e.g. |s| = 5e302 and a translation of 1e-132);
  /// `translation` and the witnesses stay accurate.
  T parameter = T(0);
  /// Outward normal of the face of M hit by the line (world frame), unit for inexact T;
  /// for exact T unnormalised (exact direction). As a contact normal it points from P
  /// towards Q: moving Q along +normal separates the two. NoContact found by the centre of
  /// duality (the usual case): a direction orthogonal to s (up to rounding for inexact T)
  /// along which all of M lies strictly below the line, a separating direction; then
  /// featureP / featureQ are the vertices of P and of Q supporting M there (P's maximum
  /// along normal, Q's minimum). Otherwise zero and -1.
  Vec3<T> normal = Vec3<T>::Zero();
  /// Contact witnesses (world frame): witnessP on P, witnessQ on Q at its *given* pose,
  /// with witnessP - witnessQ == parameter * s: moving Q by that motion brings witnessQ
  /// onto witnessP.
  Vec3<T> witnessP = Vec3<T>::Zero();
  Vec3<T> witnessQ = Vec3<T>::Zero();
  MddFaceType faceType = MddFaceType::None;
  int featureP = -1;  ///< face / vertex / edge id on P, per faceType (NoContact: see normal)
  int featureQ = -1;  ///< vertex / face / edge id on Q, per faceType (NoContact: see normal)
  /// featureP and featureQ with their kinds, as faceType implies them (FV: a face of P and
  /// a vertex of Q; VF: a vertex of P and a face of Q; EE: two edges; Grazing and
  /// NoContact's separating normal: two vertices); kind None and index -1 where unset.
  Feature featureOfP() const noexcept { return detail::typedFeature(faceType, true, featureP); }
  Feature featureOfQ() const noexcept { return detail::typedFeature(faceType, false, featureQ); }
  /// Faces of M evaluated, per phase (summed over the d_max and d_min searches).
  int visitedFV = 0, visitedVF = 0, visitedEE = 0;
  /// True when a scan quadratic in the sizes ran: the local search's answer failed its
  /// check (the hit point must lie in the face found) and the exhaustive search over all
  /// FV, VF and EE faces answered instead, or the chord of M (the line clipped by every
  /// face plane of M) did.
  bool usedFallback = false;
  /// Which step answered (see MddPath); with faceType, what the paper's "faces visited"
  /// counts above were spent on.
  MddPath path = MddPath::None;
  /// True when SEARCH-EE tested all deg(u) · deg(w) edge pairs at a vertex pair whose
  /// degrees both exceed defaults::kMddChaseMinDegree (quadratic in the degrees): the
  /// chase of their Gauss regions (mdd/detail/region_crossings.hpp) could not run there,
  /// the two regions not fitting in one hemisphere together.
  bool usedPairScan = false;
  /// Support queries on M made by the exit-portal estimates (mdd/detail/exit_portal.hpp), the
  /// starting points of the searches; 0 when a cached face answered.
  int portalSteps = 0;
  /// True when mdd() answered for a direction other than s as given: a component of s
  /// below the unit roundoff times its largest (inexact T) is taken as 0 (the line is
  /// tilted by less than the rounding of any product with s). `parameter` and
  /// `translation` are for that direction.
  bool directionRounded = false;
  /// True when the faces kept in the MddCache from the last query answered this one
  /// (each certified by the facet check), without the centre of duality or any search.
  bool fromCache = false;
};

/// A face of M named by its features, as kept between queries: FV (face of P, vertex of
/// Q), VF (vertex of P, face of Q) or EE (edge of P, edge of Q).
struct MddCachedFace {
  MddFaceType type = MddFaceType::None;
  int a = -1, b = -1;
};

namespace detail {
/// Open-addressing set of int pairs with epoch clearing (visited EE faces, section VI-D).
class PairMarks {
 public:
  void reset() {
    if (keys_.empty()) grow(256);
    if (++epoch_ == 0) {
      std::fill(stamp_.begin(), stamp_.end(), 0u);
      epoch_ = 1;
    }
    count_ = 0;
  }
  bool mark(int a, int b) {
    if (2 * (count_ + 1) > keys_.size()) rehash();
    const std::uint64_t k = (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
                            static_cast<std::uint32_t>(b);
    std::size_t i = hash(k) & (keys_.size() - 1);
    while (stamp_[i] == epoch_) {
      if (keys_[i] == k) return false;
      i = (i + 1) & (keys_.size() - 1);
    }
    stamp_[i] = epoch_;
    keys_[i] = k;
    ++count_;
    return true;
  }

  /// Calls f(a, b) for every pair marked since the last reset.
  template <class F>
  void forEach(F&& f) const {
    for (std::size_t i = 0; i < keys_.size(); ++i)
      if (stamp_[i] == epoch_) f(static_cast<int>(keys_[i] >> 32), static_cast<int>(keys_[i] & 0xffffffffu));
  }

 private:
  static std::size_t hash(std::uint64_t k) {
    k ^= k >> 33;
    k *= 0xff51afd7ed558ccdULL;
    k ^= k >> 33;
    return static_cast<std::size_t>(k);
  }
  void grow(std::size_t n) {
    keys_.assign(n, 0);
    stamp_.assign(n, 0);
  }
  void rehash() {
    std::vector<std::uint64_t> old;
    for (std::size_t i = 0; i < keys_.size(); ++i)
      if (stamp_[i] == epoch_) old.push_back(keys_[i]);
    grow(keys_.size() * 2);
    epoch_ = 1;
    count_ = 0;
    for (std::uint64_t k : old) mark(static_cast<int>(k >> 32), static_cast<int>(k & 0xffffffffu));
  }
  std::vector<std::uint64_t> keys_;
  std::vector<std::uint32_t> stamp_;
  std::uint32_t epoch_ = 0;
  std::size_t count_ = 0;
};
/// Marks on ids (faces or vertices of one shape) with the same O(1) clearing. Hashed at
/// first, not an array indexed by id: a query touches a few dozen ids, and sizing an
/// array to a 100k-vertex shape would cost a cold query (no cache kept) O(n) time and
/// memory. Once a pass marks more than an eighth of the ids (the support set of a
/// 1024-gon cap: thousands of hashed inserts and rehashes, most of a resting contact's
/// query), the marks move to an array of epoch stamps, which then serves every later
/// pass over at most as many ids: its O(n) cost is paid only where a pass is O(n) anyway.
class EpochMarks {
 public:
  void reset(std::size_t ids) {
    ids_ = ids;
    count_ = 0;
    dense_ = !stamp_.empty() && ids <= stamp_.size();
    if (!dense_) {
      set_.reset();
    } else if (++epoch_ == 0) {
      std::fill(stamp_.begin(), stamp_.end(), 0u);
      epoch_ = 1;
    }
  }
  /// True if i was not marked yet (and marks it).
  bool mark(int i) {
    if (dense_) {
      if (stamp_[static_cast<std::size_t>(i)] == epoch_) return false;
      stamp_[static_cast<std::size_t>(i)] = epoch_;
      return true;
    }
    if (!set_.mark(i, 0)) return false;
    if (++count_ * 8 > ids_) toArray();
    return true;
  }

 private:
  void toArray() {
    stamp_.assign(ids_, 0u);
    epoch_ = 1;
    set_.forEach([&](int i, int) { stamp_[static_cast<std::size_t>(i)] = epoch_; });
    dense_ = true;
  }
  PairMarks set_;
  std::vector<std::uint32_t> stamp_;
  std::uint32_t epoch_ = 0;
  std::size_t ids_ = 0, count_ = 0;
  bool dense_ = false;
};
/// A pose that passed the query's checks and its inverse rotation (MddCache::checkedPoseP):
/// a shape that stays where it is (a static obstacle) is checked and inverted once, not on
/// every query. A pose matches only bit for bit (float and double) or exactly (exact T);
/// other scalar types are never kept.
template <class T>
struct CheckedPose {
  Pose<T> pose;
  Mat3<T> inverseRotation;
  bool identityRotation = false;  ///< pose.rotation is exactly the identity (so is its inverse)
  bool valid = false;
  bool matches(const Pose<T>& p) const {
    if (!valid) return false;
    if constexpr (std::is_same<T, float>::value || std::is_same<T, double>::value) {
      using Bits = std::conditional_t<sizeof(T) == 8, std::uint64_t, std::uint32_t>;
      auto same = [](const T* a, const T* b, int n) {
        Bits diff = 0;
        for (int i = 0; i < n; ++i) {
          Bits x, y;
          std::memcpy(&x, a + i, sizeof(T));
          std::memcpy(&y, b + i, sizeof(T));
          diff |= x ^ y;
        }
        return diff == 0;
      };
      return same(p.rotation.data(), pose.rotation.data(), 9) && same(p.translation.data(), pose.translation.data(), 3);
    } else if constexpr (ScalarTraits<T>::isExact) {
      return p.rotation == pose.rotation && p.translation == pose.translation;
    } else {
      return false;
    }
  }
  void keep(const Pose<T>& p, const Mat3<T>& inverse) {
    pose = p;
    inverseRotation = inverse;
    identityRotation = p.rotation == Mat3<T>::Identity();
    valid = true;
  }
};
}  // namespace detail

/// Per-pair state a caller may keep between queries (frame coherence, section VI-E):
/// the last optimal face of P seeds the next SEARCH-FV, the last support vertices warm
/// the support queries, and the visited-marks buffers are reused, so a warm query does
/// not allocate. One cache per (P, Q) pair and scalar type; not thread-safe (one per
/// thread).
template <class T>
struct MddCache {
  int faceP = -1;    ///< seed face of P for SEARCH-FV
  int vertexP = -1;  ///< last support vertex of P
  int vertexQ = -1;  ///< last support vertex of Q
  /// The last exit faces found on each side of the line: [0] the exit along +s, [1] along
  /// −s (a penetrating query whose first exit is nearer than the centre of duality
  /// updates only that side).
  MddCachedFace exitFaces[2];
  const void* shapeP = nullptr;  ///< identity of the shapes the hints belong to
  const void* shapeQ = nullptr;
  detail::EpochMarks marksP, marksQ;
  detail::PairMarks marksEE;
  std::vector<int> edgesP, edgesQ;  // EE candidate edge buffers of the portal start
  detail::RegionCrossings<T> crossings;  // SEARCH-EE's chase at high-degree vertex pairs
  // Facet-check and grazing buffers.
  std::vector<int> setP, setQ;
  std::vector<std::pair<std::pair<T, T>, int>> points2, hull2;
  detail::DifferencePolygon<T> facet;
  detail::CheckedPose<T> checkedPoseP;  // poseP of an earlier query, checked, and its inverse
};

namespace detail {

/// The cache of the overloads that take none (mdd, intersects, tryIntersects,
/// firstContact): one per thread and scalar type, its hints and kept faces cleared on each
/// call, so that the answer is that of a fresh MddCache, and its work buffers kept, so that
/// such a call allocates nothing once they have grown to the shapes' sizes (a fresh cache
/// per call was about a fifth of a cold query). The buffers stay allocated for the thread's
/// lifetime. Not for a caller that already holds it (no overload calls another).
template <class T>
MddCache<T>& scratchCache() {
  static thread_local MddCache<T> cache;
  cache.faceP = cache.vertexP = cache.vertexQ = -1;
  cache.exitFaces[0] = cache.exitFaces[1] = MddCachedFace{};
  cache.shapeP = cache.shapeQ = nullptr;
  return cache;
}

}  // namespace detail

}  // namespace mink
