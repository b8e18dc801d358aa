// tests/mdd/mdd_types_test.cpp — the names of mdd()'s enumerations (mink/mdd/mdd_types.hpp):
// every enumerator has its own spelling, usable at compile time, and a value outside the
// enumeration (a corrupted or future value cast in) is "?", not undefined behaviour.
#include "mink/mdd/mdd_types.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace {

static_assert(mink::toString(mink::MddStatus::Penetrating)[0] == 'P', "usable in constant expressions");

TEST(MddTypes, EveryEnumeratorHasItsOwnName) {
  using mink::MddFaceType;
  using mink::MddPath;
  using mink::MddStatus;
  EXPECT_STREQ(mink::toString(MddStatus::Separated), "Separated");
  EXPECT_STREQ(mink::toString(MddStatus::Touching), "Touching");
  EXPECT_STREQ(mink::toString(MddStatus::Penetrating), "Penetrating");
  EXPECT_STREQ(mink::toString(MddStatus::NoContact), "NoContact");
  EXPECT_STREQ(mink::toString(MddStatus::IterationLimit), "IterationLimit");

  const MddPath paths[] = {MddPath::None,       MddPath::Cache, MddPath::Certificate, MddPath::Search,
                           MddPath::Exhaustive, MddPath::Chord, MddPath::Grazing};
  const char* pathNames[] = {"None", "Cache", "Certificate", "Search", "Exhaustive", "Chord", "Grazing"};
  for (int i = 0; i < 7; ++i) EXPECT_STREQ(mink::toString(paths[i]), pathNames[i]);

  const MddFaceType faces[] = {MddFaceType::None, MddFaceType::FV, MddFaceType::VF, MddFaceType::EE,
                               MddFaceType::Grazing};
  std::set<std::string> names;
  for (MddFaceType f : faces) names.insert(mink::toString(f));
  EXPECT_EQ(names, (std::set<std::string>{"None", "FV", "VF", "EE", "Grazing"}));
}

TEST(MddTypes, TypedFeaturesFollowTheFaceType) {
  using mink::FeatureKind;
  mink::MddResult<double> r;
  EXPECT_EQ(r.featureOfP(), mink::Feature{});  // nothing found: kind None, index -1
  EXPECT_EQ(r.featureOfQ().kind, FeatureKind::None);
  r.featureP = 3;
  r.featureQ = 5;
  EXPECT_EQ(r.featureOfP(), (mink::Feature{FeatureKind::Vertex, 3}));  // NoContact's separating normal
  r.faceType = mink::MddFaceType::FV;
  EXPECT_EQ(r.featureOfP(), (mink::Feature{FeatureKind::Face, 3}));
  EXPECT_EQ(r.featureOfQ(), (mink::Feature{FeatureKind::Vertex, 5}));
  r.faceType = mink::MddFaceType::VF;
  EXPECT_EQ(r.featureOfP(), (mink::Feature{FeatureKind::Vertex, 3}));
  EXPECT_EQ(r.featureOfQ(), (mink::Feature{FeatureKind::Face, 5}));
  r.faceType = mink::MddFaceType::EE;
  EXPECT_EQ(r.featureOfP(), (mink::Feature{FeatureKind::Edge, 3}));
  EXPECT_NE(r.featureOfQ(), (mink::Feature{FeatureKind::Edge, 3}));
  r.faceType = mink::MddFaceType::Grazing;
  EXPECT_EQ(r.featureOfQ(), (mink::Feature{FeatureKind::Vertex, 5}));
  EXPECT_STREQ(mink::toString(FeatureKind::Edge), "Edge");
  EXPECT_STREQ(mink::toString(static_cast<FeatureKind>(9)), "?");
}

TEST(MddTypes, AValueOutsideTheEnumerationIsAQuestionMark) {
  EXPECT_STREQ(mink::toString(static_cast<mink::MddStatus>(99)), "?");
  EXPECT_STREQ(mink::toString(static_cast<mink::MddPath>(-1)), "?");
  EXPECT_STREQ(mink::toString(static_cast<mink::MddFaceType>(42)), "?");
}

}  // namespace
