// tests/support/mdd_status.hpp — the exact reference's status (mdd_reference.hpp) as the
// mink::MddStatus a query should report, and a status's name for messages.
#pragma once

#include "mink/mdd/mdd_types.hpp"
#include "support/mdd_reference.hpp"

namespace mink_test {

inline mink::MddStatus toMinkStatus(MddRefStatus s) {
  switch (s) {
    case MddRefStatus::Separated:
      return mink::MddStatus::Separated;
    case MddRefStatus::Touching:
      return mink::MddStatus::Touching;
    case MddRefStatus::Penetrating:
      return mink::MddStatus::Penetrating;
    default:
      return mink::MddStatus::NoContact;
  }
}

inline const char* statusName(mink::MddStatus s) {
  switch (s) {
    case mink::MddStatus::Separated:
      return "Separated";
    case mink::MddStatus::Touching:
      return "Touching";
    case mink::MddStatus::Penetrating:
      return "Penetrating";
    case mink::MddStatus::NoContact:
      return "NoContact";
    case mink::MddStatus::IterationLimit:
      return "IterationLimit";
  }
  return "?";
}

}  // namespace mink_test
