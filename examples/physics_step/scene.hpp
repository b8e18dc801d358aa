// examples/physics_step/scene.hpp — a small rigid-body scene whose only contact query is
// translational continuous collision detection (CCD) by the minimum directional distance.
// Eigen and mink only; the program (physics_step.cpp) and the test
// (tests/examples/physics_step_test.cpp) run the other time-of-impact methods beside it.
//
// Why MDD is a time of impact: for a body Q moving by d over a step against a static piece
// P (rotations held fixed over the step), Q moved by t·d overlaps P iff t·d ∈ M = P ⊕ −Q.
// mdd(P, Q, s = d) returns the t of smallest |t| with t·d on ∂M (`parameter`), and
// mink::firstContact (mdd/first_contact.hpp) reads the step's impact off it:
//   Separated with 0 < parameter <= 1   → impact at t = parameter,
//   Penetrating or Touching             → impact at t = 0 (overlap or contact at the start),
//   anything else (parameter < 0 or > 1, NoContact) → no impact in this step.
// The program and the test apply the same rule to the exact reference's answer.
//
// One step of the scene:
//   1. v += g·dt, d = v·dt for every active body (some are thrown down fast: ShapeDef);
//   2. sweep: every terrain piece whose AABB meets the body's AABB swept over d is a
//      candidate pair; the caller's TOI function answers each one (the scene moves by
//      mink's answer, so every method is asked the same questions);
//   3. the body moves to the earliest impact t·d, then `gap` along the contact normal
//      (outward normal of M: the way Q leaves P), loses its velocity into the piece and a
//      share `friction` of the rest;
//   4. the rest of the step's motion, projected onto the contact plane, is swept once more
//      (steps 2–3, no third sweep): that second sweep is what lets bodies slide.
// Bodies do not collide with each other; a body below kKillHeight is retired.
#pragma once

#include <mink/mink.hpp>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace physics_step {

using Vec3 = Eigen::Vector3d;

/// A convex body shape given as points (its hull is taken), shape frame, metres.
/// launchSpeed > 0 (m/s): bodies of this shape are thrown straight down at that speed
/// from above the thin shelf (the pieces a discrete check at the step's end can tunnel).
struct ShapeDef {
  std::string name;
  std::vector<Vec3> points;
  double launchSpeed = 0.0;
};

/// Scene parameters. Units: metres, seconds.
struct SceneConfig {
  int bodies = 16;
  int steps = 90;
  double dt = 1.0 / 60.0;             // s
  unsigned seed = 18;                  // std::mt19937 seed of placements and velocities
  double gap = 1e-4;                   // m, left between a body and a piece after an impact
  double friction = 0.05;              // share of the tangential velocity lost per impact
  Vec3 gravity = Vec3(0.0, 0.0, -9.81);  // m/s^2
  double spawnHalfWidth = 6.0;         // bodies start at |x|, |y| <= this
  double spawnLow = 3.0, spawnHigh = 10.0;  // and at this height (centre), m
};

inline constexpr double kKillHeight = -20.0;  // m

/// Axis-aligned box [lo, hi], world frame.
struct Aabb {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = Vec3::Constant(-std::numeric_limits<double>::infinity());
  void add(const Vec3& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  bool overlaps(const Aabb& o) const {
    return (lo.array() <= o.hi.array()).all() && (o.lo.array() <= hi.array()).all();
  }
};

/// What a TOI method says about one pair and one motion.
struct Impact {
  bool hit = false;   // impact within the step's motion (t in [0, 1])
  double toi = 1.0;   // fraction of the motion d at first contact, valid iff hit
};

/// One candidate pair of one sweep: static piece P (terrain) and moving body Q.
struct PairQuery {
  int step = 0, sweep = 0;  // sweep 0: the step's motion, 1: the slide after an impact
  int body = -1, piece = -1;
  const mink::ConvexPolyhedron<double>* P = nullptr;
  const mink::ConvexPolyhedron<double>* Q = nullptr;
  mink::Pose<double> poseP, poseQ;     // x_world = rotation * x + translation
  Vec3 d = Vec3::Zero();               // Q's motion over the sweep, world frame, metres
  mink::MddCache<double>* cache = nullptr;  // one per (body, piece), kept across steps
};

/// mink's answer for the pair, as the scene uses it: the impact and the contact normal.
struct MinkAnswer {
  mink::MddResult<double> result;
  Impact impact;
};

inline MinkAnswer minkToi(const PairQuery& q) {
  const mink::FirstContact<double> c = mink::firstContact(*q.P, q.poseP, *q.Q, q.poseQ, q.d, *q.cache);
  MinkAnswer a;
  a.result = c.mdd;
  a.impact.hit = c.hit;
  a.impact.toi = c.fraction;
  return a;
}

class Scene {
 public:
  struct Piece {
    std::string name;
    int shape = -1;  // index into terrainShapes()
    mink::Pose<double> pose;
    Aabb box;
  };
  struct Body {
    int shape = -1;  // index into bodyShapes()
    mink::Pose<double> pose;
    Vec3 velocity = Vec3::Zero();
    bool active = true;
    int impacts = 0;
  };
  struct Counters {
    long long pairs = 0, impacts = 0, iterationLimits = 0;
  };

  Scene(const std::vector<ShapeDef>& bodyShapes, const SceneConfig& config) : config_(config) {
    for (const ShapeDef& s : bodyShapes) {
      bodyShapes_.push_back(mink::ConvexPolyhedron<double>::fromPoints(s.points));
      bodyNames_.push_back(s.name);
      launchSpeed_.push_back(s.launchSpeed);
    }
    buildTerrain();
    std::mt19937 rng(config.seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> normal(0.0, 1.0);
    for (int i = 0; i < config.bodies; ++i) {
      Body b;
      b.shape = i % static_cast<int>(bodyShapes_.size());
      Eigen::Quaterniond r(normal(rng), normal(rng), normal(rng), normal(rng));
      b.pose.rotation = r.normalized().toRotationMatrix();
      const double w = config.spawnHalfWidth;
      b.pose.translation = Vec3(-w + 2 * w * unit(rng), -w + 2 * w * unit(rng),
                                config.spawnLow + (config.spawnHigh - config.spawnLow) * unit(rng));
      b.velocity = Vec3(normal(rng), normal(rng), 0.0) * 0.5;
      const double launch = launchSpeed_[static_cast<std::size_t>(b.shape)];
      if (launch > 0.0) {
        const Piece& shelf = pieces_[kShelf];
        b.pose.translation.x() = shelf.box.lo.x() + 0.5 + (shelf.box.hi.x() - shelf.box.lo.x() - 1.0) * unit(rng);
        b.pose.translation.y() = shelf.box.lo.y() + 0.5 + (shelf.box.hi.y() - shelf.box.lo.y() - 1.0) * unit(rng);
        b.pose.translation.z() += shelf.box.hi.z();
        b.velocity.z() = -launch;
      }
      bodies_.push_back(b);
    }
    caches_.resize(bodies_.size() * pieces_.size());
  }

  const std::vector<mink::ConvexPolyhedron<double>>& bodyShapes() const { return bodyShapes_; }
  const std::vector<std::string>& bodyShapeNames() const { return bodyNames_; }
  const std::vector<mink::ConvexPolyhedron<double>>& terrainShapes() const { return terrainShapes_; }
  const std::vector<Piece>& pieces() const { return pieces_; }
  const std::vector<Body>& bodies() const { return bodies_; }
  const SceneConfig& config() const { return config_; }
  const Counters& counters() const { return counters_; }

  /// World vertices of a shape at a pose (what the exact reference and the plots take).
  static std::vector<Vec3> worldVertices(const mink::ConvexPolyhedron<double>& shape,
                                         const mink::Pose<double>& pose) {
    std::vector<Vec3> out;
    out.reserve(shape.vertices().size());
    for (const Vec3& v : shape.vertices()) out.push_back(pose.apply(v));
    return out;
  }

  /// Runs one step. `toi(const PairQuery&) -> MinkAnswer` answers each candidate pair (it
  /// must call minkToi, or mdd with the same arguments; it may run other methods too).
  template <class ToiFn>
  void step(int stepIndex, ToiFn&& toi) {
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      Body& b = bodies_[i];
      if (!b.active) continue;
      b.velocity += config_.gravity * config_.dt;
      const Vec3 d = b.velocity * config_.dt;
      Vec3 normal;
      double t = sweep(stepIndex, 0, static_cast<int>(i), d, normal, toi);
      if (t < 1.0) {
        // Slide: the rest of the motion, projected onto the contact plane.
        Vec3 rest = (1.0 - t) * (d - d.dot(normal) * normal);
        if (rest.squaredNorm() > 0.0) {
          Vec3 n2;
          sweep(stepIndex, 1, static_cast<int>(i), rest, n2, toi);
        }
      }
      if (b.pose.translation.z() < kKillHeight) b.active = false;
    }
  }

 private:
  // Returns the fraction of d moved (1: no impact) and the normal of the impact.
  template <class ToiFn>
  double sweep(int stepIndex, int sweepIndex, int bi, const Vec3& d, Vec3& normal, ToiFn&& toi) {
    Body& b = bodies_[static_cast<std::size_t>(bi)];
    const mink::ConvexPolyhedron<double>& Q = bodyShapes_[static_cast<std::size_t>(b.shape)];
    Aabb swept;
    for (const Vec3& v : Q.vertices()) {
      const Vec3 w = b.pose.apply(v);
      swept.add(w);
      swept.add(w + d);
    }
    swept.lo.array() -= config_.gap;
    swept.hi.array() += config_.gap;
    double best = 2.0;
    normal = Vec3::Zero();
    for (std::size_t k = 0; k < pieces_.size(); ++k) {
      const Piece& piece = pieces_[k];
      if (!swept.overlaps(piece.box)) continue;
      PairQuery q;
      q.step = stepIndex;
      q.sweep = sweepIndex;
      q.body = bi;
      q.piece = static_cast<int>(k);
      q.P = &terrainShapes_[static_cast<std::size_t>(piece.shape)];
      q.Q = &Q;
      q.poseP = piece.pose;
      q.poseQ = b.pose;
      q.d = d;
      q.cache = &caches_[static_cast<std::size_t>(bi) * pieces_.size() + k];
      const MinkAnswer a = toi(q);
      ++counters_.pairs;
      if (a.result.status == mink::MddStatus::IterationLimit) ++counters_.iterationLimits;
      if (a.impact.hit && a.impact.toi < best) {
        best = a.impact.toi;
        normal = a.result.normal;
      }
    }
    if (best > 1.0) {
      b.pose.translation += d;
      return 1.0;
    }
    ++counters_.impacts;
    ++b.impacts;
    // normal is the outward normal of M at the contact: Q leaves P along +normal.
    b.pose.translation += best * d + config_.gap * normal;
    const double vn = b.velocity.dot(normal);
    if (vn < 0.0) b.velocity -= vn * normal;
    b.velocity *= 1.0 - config_.friction;
    return best;
  }

  void addBox(const std::string& name, const Vec3& half, const Vec3& centre, const Eigen::Matrix3d& rotation) {
    std::vector<Vec3> pts;
    for (int i = 0; i < 8; ++i)
      pts.emplace_back((i & 1 ? 1 : -1) * half.x(), (i & 2 ? 1 : -1) * half.y(), (i & 4 ? 1 : -1) * half.z());
    terrainShapes_.push_back(mink::ConvexPolyhedron<double>::fromPoints(pts));
    Piece p;
    p.name = name;
    p.shape = static_cast<int>(terrainShapes_.size()) - 1;
    p.pose.rotation = rotation;
    p.pose.translation = centre;
    for (const Vec3& v : terrainShapes_.back().vertices()) p.box.add(p.pose.apply(v));
    pieces_.push_back(p);
  }

  // A floor slab (top face at z = 0), two ramps tilted towards it, a low block and a thin
  // shelf (5 cm) above the floor.
  static constexpr std::size_t kShelf = 4;
  void buildTerrain() {
    const double kPi = 3.14159265358979323846;
    addBox("slab", Vec3(10.0, 10.0, 0.5), Vec3(0.0, 0.0, -0.5), Eigen::Matrix3d::Identity());
    addBox("ramp-x", Vec3(3.0, 2.5, 0.25), Vec3(-3.5, 0.0, 1.6),
           Eigen::AngleAxisd(25.0 * kPi / 180.0, Vec3::UnitY()).toRotationMatrix());
    addBox("ramp-y", Vec3(2.5, 3.0, 0.25), Vec3(3.0, 3.0, 1.2),
           Eigen::AngleAxisd(-20.0 * kPi / 180.0, Vec3::UnitX()).toRotationMatrix());
    addBox("block", Vec3(1.5, 1.5, 0.4), Vec3(3.0, -3.5, 0.4),
           Eigen::AngleAxisd(30.0 * kPi / 180.0, Vec3::UnitZ()).toRotationMatrix());
    addBox("shelf", Vec3(3.0, 2.4, 0.025), Vec3(-2.5, -5.1, 2.2), Eigen::Matrix3d::Identity());
  }

  SceneConfig config_;
  std::vector<mink::ConvexPolyhedron<double>> bodyShapes_, terrainShapes_;
  std::vector<std::string> bodyNames_;
  std::vector<double> launchSpeed_;
  std::vector<Piece> pieces_;
  std::vector<Body> bodies_;
  std::vector<mink::MddCache<double>> caches_;
  Counters counters_;
};

}  // namespace physics_step
