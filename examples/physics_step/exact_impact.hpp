// examples/physics_step/exact_impact.hpp — the exact reference's impact for one recorded
// pair query: the CGAL hull of all vertex differences of the two placed shapes
// (tests/support/mdd_reference.hpp, Gmpq), the line of the step's displacement clipped
// exactly. An impact in the step iff the pair overlaps or touches at the start, or the
// exact parameter t of the contact lies in [0, 1]. Shared by the program and its test, so
// that the test checks the rule the table is made with.
#pragma once

#include <CGAL/Gmpq.h>

#include "physics_step/scene.hpp"
#include "support/mdd_reference.hpp"

namespace physics_step {

inline Impact exactImpactOf(const mink_test::MddRefResult& r) {
  Impact e;
  if (r.status == mink_test::MddRefStatus::Penetrating || r.status == mink_test::MddRefStatus::Touching) {
    e.hit = true;
    e.toi = 0.0;
  } else if (r.status == mink_test::MddRefStatus::Separated && r.t >= 0 && r.t <= 1) {
    e.hit = true;
    e.toi = CGAL::to_double(r.t);
  }
  return e;
}

/// The exact reference's answer for q, and the result it was read from.
inline Impact exactImpact(const PairQuery& q, mink_test::MddRefResult* result = nullptr) {
  const mink_test::MinkowskiDifferenceReference ref(Scene::worldVertices(*q.P, q.poseP),
                                                    Scene::worldVertices(*q.Q, q.poseQ));
  const mink_test::MddRefResult r = ref.query(q.d);
  if (result) *result = r;
  return exactImpactOf(r);
}

}  // namespace physics_step
