// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <string>

#include <gtest/gtest.h>

namespace demwb_engine_test {

/// The running test's full name as one path component ("Suite.Name", a parameterised test's '/'
/// turned into '_'): scratch folders start with it, so that two tests that run the same scene at
/// once (ctest -j) never share, and empty, each other's run directory.
inline std::string current_test_folder() {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = info == nullptr ? std::string("outside-a-test")
                                     : std::string(info->test_suite_name()) + "." + info->name();
  std::replace(name.begin(), name.end(), '/', '_');
  return name;
}

}  // namespace demwb_engine_test
