// tests/no_exceptions/mesh_io_cpd_checks.cpp — the mesh, io and CPD layers built without
// exceptions (see no_exceptions_test.cpp): TriangleMesh::tryFromMesh, tryMeshesOverlap,
// MeshOverlap::trySetPlacement, the OBJ / OFF readers' and writers' try* twins,
// tryReadTriangleMesh, LocalMinkowskiSum::tryUpdate, tryMinkowskiBoundary and the CPD / PD
// queries' status InvalidInput, on bad and good input.
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "mink/cpd/continuous_penetration_depth.hpp"
#include "mink/cpd/local_minkowski_sum.hpp"
#include "mink/cpd/minkowski_boundary.hpp"
#include "mink/io/obj.hpp"
#include "mink/io/off.hpp"
#include "mink/io/triangle_mesh_io.hpp"
#include "mink/mesh/mesh_overlap.hpp"
#include "mink/mesh/triangle_mesh.hpp"

static_assert(!MINK_EXCEPTIONS, "this file must be compiled with -fno-exceptions");

namespace mink_no_exceptions {
namespace {

using V = mink::Vec3<double>;
using Tri = std::array<int, 3>;

int failures = 0;

void check(bool ok, const std::string& what) {
  if (!ok) {
    ++failures;
    std::fprintf(stderr, "FAIL: %s\n", what.c_str());
  }
}

bool contains(const std::string& text, const char* words) { return text.find(words) != std::string::npos; }

// The unit cube [0, 1]^3, 12 triangles counter-clockwise seen from outside.
std::vector<V> cubeVertices() {
  std::vector<V> v;
  for (int i = 0; i < 8; ++i) v.push_back(V(i & 1, (i >> 1) & 1, (i >> 2) & 1));
  return v;
}
std::vector<Tri> cubeTriangles() {
  return {{{0, 2, 3}}, {{0, 3, 1}}, {{4, 5, 7}}, {{4, 7, 6}}, {{0, 1, 5}}, {{0, 5, 4}},
          {{2, 6, 7}}, {{2, 7, 3}}, {{0, 4, 6}}, {{0, 6, 2}}, {{1, 3, 7}}, {{1, 7, 5}}};
}

void checkTriangleMesh() {
  const auto good = mink::TriangleMesh<double>::tryFromMesh(cubeVertices(), cubeTriangles());
  check(good.ok() && good.value().numTriangles() == 12 && good.value().numVertices() == 8,
        "TriangleMesh::tryFromMesh on a cube: " + good.error().message());
  std::vector<Tri> open = cubeTriangles();
  open.pop_back();
  const auto r1 = mink::TriangleMesh<double>::tryFromMesh(cubeVertices(), open);
  check(!r1.ok() && contains(r1.error().message(), "is open"), "tryFromMesh on an open cube: " + r1.error().message());
  std::vector<V> nanVertex = cubeVertices();
  nanVertex[6][0] = std::numeric_limits<double>::quiet_NaN();
  const auto r2 = mink::TriangleMesh<double>::tryFromMesh(nanVertex, cubeTriangles());
  check(!r2.ok() && contains(r2.error().message(), "vertex 6 has a non-finite coordinate"),
        "tryFromMesh with a NaN vertex: " + r2.error().message());
  std::vector<Tri> outOfRange = cubeTriangles();
  outOfRange[4][1] = 8;
  const auto r3 = mink::TriangleMesh<double>::tryFromMesh(cubeVertices(), outOfRange);
  check(!r3.ok() && contains(r3.error().message(), "triangle 4 has vertex index 8 out of range"),
        "tryFromMesh with an index out of range: " + r3.error().message());
  std::vector<Tri> inward = cubeTriangles();
  for (Tri& t : inward) std::swap(t[1], t[2]);
  const auto r4 = mink::TriangleMesh<double>::tryFromMesh(cubeVertices(), inward);
  check(!r4.ok() && contains(r4.error().message(), "oriented inward"), "tryFromMesh inward: " + r4.error().message());
}

void checkQueries() {
  const auto A = mink::TriangleMesh<double>::fromMesh(cubeVertices(), cubeTriangles());
  mink::Pose<double> near, bad;
  near.translation = V(0.75, 0.1, 0.05);  // B overlaps A by 0.25 along x
  bad.translation = V(0, std::numeric_limits<double>::infinity(), 0);

  mink::MeshOverlap<double> placed(A, A, mink::Mat3<double>::Identity(), near.translation);
  const mink::Error pe0 = placed.trySetPlacement(mink::Mat3<double>::Identity(), bad.translation);
  check(pe0 && contains(pe0.message(), "MeshOverlap: placement.translation is not finite") && placed.overlaps(),
        "MeshOverlap::trySetPlacement with an infinite translation: " + pe0.message());
  check(!placed.trySetPlacement(mink::Mat3<double>::Identity(), mink::Vec3<double>(3, 0, 0)) && !placed.overlaps(),
        "MeshOverlap::trySetPlacement apart");

  const auto o = mink::tryMeshesOverlap(A, mink::Pose<double>(), A, near);
  check(o.ok() && o.value(), "tryMeshesOverlap on overlapping cubes");
  const auto ob = mink::tryMeshesOverlap(A, mink::Pose<double>(), A, bad);
  check(!ob.ok() && contains(ob.error().message(), "poseB.translation is not finite"),
        "tryMeshesOverlap with a bad pose: " + ob.error().message());

  mink::LocalMinkowskiSum<double> sum(A, A);
  const auto u0 = sum.tryUpdate(mink::Pose<double>(), near, V(0, 0, 0), 0.0);
  check(!u0.ok() && contains(u0.error().message(), "radius must be positive"),
        "LocalMinkowskiSum::tryUpdate with radius 0: " + u0.error().message());
  const auto u1 = sum.tryUpdate(mink::Pose<double>(), near, V(0.25, 0, 0), 0.3);  // on the face x = 0.25 of M
  check(u1.ok() && !u1.value()->triangles.empty(), "LocalMinkowskiSum::tryUpdate on a good ball");
  const auto u2 = sum.tryUpdate(mink::Pose<double>(), near, V(0.25, 0, 0), -1.0);
  check(!u2.ok() && contains(u2.error().message(), "LocalMinkowskiSum::update: the ball's radius"),
        "LocalMinkowskiSum::tryUpdate with radius -1: " + u2.error().message());
  const auto b0 = mink::tryMinkowskiBoundary(A, bad, A, near);
  check(!b0.ok() && contains(b0.error().message(), "minkowskiBoundary: poseA.translation is not finite"),
        "tryMinkowskiBoundary with a bad pose: " + b0.error().message());
  const auto b1 = mink::tryMinkowskiBoundary(A, mink::Pose<double>(), A, near);
  check(b1.ok() && !b1.value().triangles.empty(), "tryMinkowskiBoundary on overlapping cubes");

  // CPD: good input answered, bad pose and bad options give the status InvalidInput.
  mink::ContinuousPenetrationDepth<double> cpd(A, A);
  check(!cpd.error(), "ContinuousPenetrationDepth with default options has no error");
  const mink::CpdResult<double> r = cpd.query(mink::Pose<double>(), near);
  check(r.status == mink::CpdStatus::Penetrating && std::abs(r.depth - 0.25) < 1e-9,
        std::string("CPD on overlapping cubes: ") + mink::toString(r.status) + " " + std::to_string(r.depth));
  const mink::CpdResult<double> rb = cpd.query(mink::Pose<double>(), bad);
  check(rb.status == mink::CpdStatus::InvalidInput && std::isnan(rb.depth) && std::isnan(rb.point[0]),
        std::string("CPD with a bad pose: ") + mink::toString(rb.status));
  check(contains(cpd.error().message(), "ContinuousPenetrationDepth::query: poseB.translation is not finite"),
        "ContinuousPenetrationDepth::error() after a bad pose: " + cpd.error().message());
  const mink::Error pe = mink::checkCpdInput(mink::Pose<double>(), bad);
  check(pe && contains(pe.message(), "ContinuousPenetrationDepth::query: poseB.translation is not finite"),
        "checkCpdInput: " + pe.message());
  const mink::CpdResult<double> again = cpd.query(mink::Pose<double>(), near);
  check(again.status == mink::CpdStatus::Penetrating && again.depth == r.depth, "CPD after a rejected query");
  check(!cpd.error(), "ContinuousPenetrationDepth::error() after a good query: " + cpd.error().message());

  mink::CpdOptions<double> badOptions;
  badOptions.beta = 0.5;
  mink::ContinuousPenetrationDepth<double> broken(A, A, badOptions);
  check(broken.error() && contains(broken.error().message(), "beta must be greater than 1"),
        "ContinuousPenetrationDepth::error() with beta 0.5: " + broken.error().message());
  const mink::CpdResult<double> ro = broken.query(mink::Pose<double>(), near);
  check(ro.status == mink::CpdStatus::InvalidInput && std::isnan(ro.depth), "CPD with bad options");
  check(mink::checkCpdOptions(badOptions).message() == broken.error().message(), "checkCpdOptions");

  const mink::CpdResult<double> pd = mink::penetrationDepth(A, mink::Pose<double>(), A, near);
  check(pd.status == mink::CpdStatus::Penetrating && std::abs(pd.depth - 0.25) < 1e-9, "penetrationDepth");
  const mink::CpdResult<double> pdb = mink::penetrationDepth(A, bad, A, near);
  check(pdb.status == mink::CpdStatus::InvalidInput, "penetrationDepth with a bad pose");
  const mink::CpdResult<double> pdo = mink::penetrationDepth(A, mink::Pose<double>(), A, near, badOptions);
  check(pdo.status == mink::CpdStatus::InvalidInput, "penetrationDepth with bad options");
}

const char* const kCubeObj =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";

void checkReaders() {
  std::istringstream badObj("v 0 0 0\nv 1 x 0\n");
  const auto o1 = mink::io::tryReadObj<double>(badObj, "bad.obj");
  check(!o1.ok() && contains(o1.error().message(), "mink: bad.obj:2: 'x' is not a finite number"),
        "tryReadObj on a malformed vertex: " + o1.error().message());
  std::istringstream goodObj(kCubeObj);
  const auto o2 = mink::io::tryReadObj<double>(goodObj, "cube.obj");
  check(o2.ok() && o2.value().vertices.size() == 8 && o2.value().faces.size() == 6,
        "tryReadObj on a cube: " + o2.error().message());

  std::istringstream badOff("OFF\n3 1 0\n0 0 0\n1 0 0\n");
  const auto f1 = mink::io::tryReadOff<double>(badOff, "bad.off");
  check(!f1.ok() && contains(f1.error().message(), "bad.off:4: file ends after 2 of 3 vertices"),
        "tryReadOff on a truncated file: " + f1.error().message());
  std::istringstream goodOff("OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n");
  const auto f2 = mink::io::tryReadOff<double>(goodOff, "tet.off");
  check(f2.ok() && f2.value().vertices.size() == 4 && f2.value().faces.size() == 4,
        "tryReadOff on a tetrahedron: " + f2.error().message());

  const std::vector<V> v = {V(0, 0, 0), V(1, 0, 0), V(0, 1, 0)};
  std::ostringstream out;
  const mink::Error w1 = mink::io::tryWriteOff(out, v, {{0, 1, 3}});
  check(w1 && contains(w1.message(), "writeOff: face 0 has index 3 outside [0, 3)") && out.str().empty(),
        "tryWriteOff with an index out of range: " + w1.message());
  const mink::Error w2 = mink::io::tryWriteObj(out, v, {{0, 1, 2}});
  check(!w2 && contains(out.str(), "f 1 2 3"), "tryWriteObj on a triangle: " + w2.message());

  // Files: a scratch directory of its own, removed at the end (error_code overloads: the
  // others throw).
  std::error_code ec;
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path(ec) /
      ("mink_no_exceptions_" + std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()));
  if (ec || !std::filesystem::create_directories(dir, ec)) {
    check(false, "cannot create a scratch directory: " + ec.message());
    return;
  }
  const auto write = [&](const char* name, const std::string& text) {
    std::ofstream(dir / name, std::ios::binary) << text;
    return dir / name;
  };
  const auto t1 = mink::io::tryReadTriangleMesh<double>(write("cube.obj", kCubeObj));
  check(t1.ok() && t1.value().numTriangles() == 12, "tryReadTriangleMesh on a cube: " + t1.error().message());
  const auto t2 =
      mink::io::tryReadTriangleMesh<double>(write("broken.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"));
  check(!t2.ok() && contains(t2.error().message(), "broken.off:6: '7' is not a vertex index in [0, 3)"),
        "tryReadTriangleMesh on a malformed OFF file: " + t2.error().message());
  const auto t3 = mink::io::tryReadTriangleMesh<double>(write("open.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
  check(!t3.ok() && contains(t3.error().message(), "open.obj: TriangleMesh::fromMesh: edge") &&
            contains(t3.error().message(), "is open"),
        "tryReadTriangleMesh on an open mesh: " + t3.error().message());
  const auto t4 = mink::io::tryReadTriangleMesh<double>(dir / "absent.off");
  check(!t4.ok() && contains(t4.error().message(), "cannot open OFF file"),
        "tryReadTriangleMesh on a missing file: " + t4.error().message());
  const auto t5 = mink::io::tryReadTriangleMesh<double>(write("cube.stl", "solid\n"));
  check(!t5.ok() && contains(t5.error().message(), "is neither .obj nor .off"),
        "tryReadTriangleMesh on an STL file: " + t5.error().message());
  const mink::Error w3 = mink::io::tryWriteOff(dir / "tri.off", v, {{0, 2, 1}});
  const auto r3 = mink::io::tryReadOff<double>(dir / "tri.off");
  check(!w3 && r3.ok() && r3.value().faces.size() == 1 && r3.value().faces[0][1] == 2,
        "tryWriteOff then tryReadOff: " + w3.message() + r3.error().message());
  const mink::Error w4 = mink::io::tryWriteObj(dir / "no_such_dir" / "tri.obj", v, {{0, 2, 1}});
  check(w4 && contains(w4.message(), "cannot create OBJ file"),
        "tryWriteObj into a missing directory: " + w4.message());
  std::filesystem::remove_all(dir, ec);
}

}  // namespace

int checkMeshIoCpd() {
  checkTriangleMesh();
  checkReaders();
  checkQueries();
  return failures;
}

}  // namespace mink_no_exceptions
