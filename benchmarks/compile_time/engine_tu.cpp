// benchmarks/compile_time/engine_tu.cpp — a translation unit as a physics engine writes
// one: includes <mink/mink.hpp>, builds two hulls and calls mdd, intersects and
// firstContact in double. run_compile_time.sh times its compilation with and without
// MINK_EXTERN_TEMPLATES (the entry points then come from src/mink_instantiations.cpp).
#include <mink/mink.hpp>

#include <cstdio>
#include <vector>

int main() {
  std::vector<mink::Vec3<double>> corners;
  for (int i = 0; i < 8; ++i) corners.emplace_back(i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0);
  const auto box = mink::ConvexPolyhedron<double>::fromPoints(corners);
  mink::Pose<double> p, q;
  q.translation = mink::Vec3<double>(3.0, 0.25, 0.0);
  mink::MddCache<double> cache;
  const auto r = mink::mdd(box, p, box, q, mink::Vec3<double>(-1.0, 0.0, 0.0), cache);
  const bool hit = mink::intersects(box, p, box, q, cache);
  const auto fc = mink::firstContact(box, p, box, q, mink::Vec3<double>(-2.0, 0.0, 0.0), cache);
  std::printf("%d %g %d %d %g\n", static_cast<int>(r.status), r.translation, int(hit), int(fc.hit), fc.fraction);
  return 0;
}
