// SPDX-License-Identifier: MIT
#include "reports/junit.hpp"

#include <fmt/format.h>

namespace reports {

std::string xml_escape(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

namespace {

std::string describe(const comparison::Comparison& c) {
  std::string d = fmt::format("{} {} vs {}: ", c.metric, c.engine, c.reference);
  if (c.value && c.reference_value) {
    d += fmt::format("{:.9g} vs {:.9g} (abs diff {:.3g}, tolerance rel {:.3g} abs {:.3g})", *c.value,
                     *c.reference_value, c.abs_diff.value_or(0.0), c.tolerance.rel, c.tolerance.abs);
  }
  if (!c.note.empty()) d += (c.value ? "; " : "") + c.note;
  return d;
}

}  // namespace

std::string junit_xml(const std::vector<const comparison::CaseOutcome*>& outcomes,
                      const std::string& suite_name,
                      const std::vector<std::pair<std::string, std::string>>& broken_cases) {
  std::string body;
  std::size_t total = 0, failures = 0, errors = 0, skipped = 0;
  for (const auto* o : outcomes) {
    std::size_t f = 0, e = 0, s = 0;
    std::string cases_xml;
    for (const auto& c : o->comparisons) {
      cases_xml += fmt::format("    <testcase classname=\"{}.{}\" name=\"{}\">", xml_escape(o->scene.name),
                               xml_escape(c.engine), xml_escape(c.metric));
      const std::string msg = xml_escape(describe(c));
      switch (c.status) {
        case comparison::Status::pass: break;
        case comparison::Status::fail:
          cases_xml += fmt::format("<failure message=\"{}\" type=\"fail\"/>", msg);
          ++f;
          break;
        case comparison::Status::error:
        case comparison::Status::missing:
          cases_xml += fmt::format("<error message=\"{}\" type=\"{}\"/>", msg, comparison::to_string(c.status));
          ++e;
          break;
        case comparison::Status::not_applicable:
          cases_xml += fmt::format("<skipped message=\"{}\"/>", msg);
          ++s;
          break;
      }
      cases_xml += "</testcase>\n";
    }
    body += fmt::format("  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"{}\" skipped=\"{}\">\n{}  </testsuite>\n",
                        xml_escape(o->scene.name), o->comparisons.size(), f, e, s, cases_xml);
    total += o->comparisons.size();
    failures += f;
    errors += e;
    skipped += s;
  }
  for (const auto& [name, reason] : broken_cases) {
    body += fmt::format("  <testsuite name=\"{0}\" tests=\"1\" failures=\"0\" errors=\"1\" skipped=\"0\">\n"
                        "    <testcase classname=\"{0}\" name=\"load\"><error message=\"{1}\" type=\"case\"/></testcase>\n"
                        "  </testsuite>\n",
                        xml_escape(name), xml_escape(reason));
    ++total;
    ++errors;
  }
  return fmt::format("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"{}\" skipped=\"{}\">\n{}</testsuites>\n",
                     xml_escape(suite_name), total, failures, errors, skipped, body);
}

}  // namespace reports
