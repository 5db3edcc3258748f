// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "compare/case_outcome.hpp"

namespace reports {

/// A JUnit XML document for CI systems: one <testsuite> per case, one <testcase> per
/// (engine, metric) comparison. fail → <failure>, error and missing → <error> (they never pass),
/// n/a → <skipped> with its reason.
/// Case files that could not be loaded appear as one erroring testcase each (name, reason).
std::string junit_xml(const std::vector<const comparison::CaseOutcome*>& outcomes,
                      const std::string& suite_name,
                      const std::vector<std::pair<std::string, std::string>>& broken_cases = {});

/// `text` with the five XML special characters escaped.
std::string xml_escape(const std::string& text);

}  // namespace reports
