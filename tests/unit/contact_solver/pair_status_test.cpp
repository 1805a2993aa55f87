// The status the outputs report per pair: bonded while adhesion is active (β > 0), the contact
// branch otherwise (issue 13: a bonded pair under shear used to read "slip").

#include "contact/solver/interface_assembler.hpp"

#include <gtest/gtest.h>

#include <string>

namespace bipot::contact {
namespace {

PairResult pair(double beta, ContactStatus status) {
  PairResult r;
  r.beta = beta;
  r.status = status;
  return r;
}

TEST(PairStatus, AdhesionStillActiveIsBondedWhateverTheBranch) {
  // A sound bond in shear: μ̄ = μ(1 − β) = 0, so the projection is on its "slip" branch.
  for (ContactStatus s : {ContactStatus::Open, ContactStatus::Stick, ContactStatus::Slip}) {
    EXPECT_EQ(reported_status(pair(1.0, s)), PairStatus::Bonded);
    EXPECT_EQ(reported_status(pair(1e-9, s)), PairStatus::Bonded); // partly debonded
  }
}

TEST(PairStatus, DebondedPairsReportTheirContactBranch) {
  EXPECT_EQ(reported_status(pair(0.0, ContactStatus::Open)), PairStatus::Open);
  EXPECT_EQ(reported_status(pair(0.0, ContactStatus::Stick)), PairStatus::Stick);
  EXPECT_EQ(reported_status(pair(0.0, ContactStatus::Slip)), PairStatus::Slip);
}

TEST(PairStatus, CodesAndNamesAreTheDocumentedOnes) {
  // docs/input_reference.md (VTK `status`) and docs/pile_pullout.md (profiles.csv).
  EXPECT_EQ(static_cast<int>(PairStatus::Open), 0);
  EXPECT_EQ(static_cast<int>(PairStatus::Stick), 1);
  EXPECT_EQ(static_cast<int>(PairStatus::Slip), 2);
  EXPECT_EQ(static_cast<int>(PairStatus::Bonded), 3);
  EXPECT_EQ(std::string(to_string(PairStatus::Open)), "open");
  EXPECT_EQ(std::string(to_string(PairStatus::Stick)), "stick");
  EXPECT_EQ(std::string(to_string(PairStatus::Slip)), "slip");
  EXPECT_EQ(std::string(to_string(PairStatus::Bonded)), "bonded");
}

} // namespace
} // namespace bipot::contact
