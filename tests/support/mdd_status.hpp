// tests/support/mdd_status.hpp — the exact reference's status (mdd_reference.hpp) as the
// mink::MddStatus a query should report (a status's name: mink::toString).
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

}  // namespace mink_test
