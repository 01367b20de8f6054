// Records the worst relative residual per check and prints them when the test program ends.
#include <cstdio>
#include <map>
#include <string>

#include "truth_test_util.h"

namespace truth_test {
namespace {

std::map<std::string, Real>& worst() {
  static std::map<std::string, Real> table;
  return table;
}

class PrintWorst : public ::testing::Environment {
 public:
  void TearDown() override {
    if (worst().empty()) return;
    std::printf("[ truth   ] worst relative residuals (tolerance %.0Lg):\n", kTol);
    for (const auto& [name, value] : worst()) {
      std::printf("[ truth   ]   %-40s %.3Lg\n", name.c_str(), value);
    }
  }
};

// Registered before main() runs; gtest owns and deletes the environment.
[[maybe_unused]] ::testing::Environment* const kPrintWorst =
    ::testing::AddGlobalTestEnvironment(new PrintWorst);

}  // namespace

void record(const std::string& name, Real relResidual) {
  Real& slot = worst()[name];
  if (relResidual > slot || std::isnan(relResidual)) slot = relResidual;
}

}  // namespace truth_test
